#pragma once
// Loads scenarios (scenarios/scenario.h documents the format) and rejects every file that is
// not exactly right: malformed JSON, unknown keys, wrong types, values out of range, missing
// required items, broken references. The first problem found is thrown as one scenario_error
// that names the file, the JSON Pointer of the offending value, the problem and the value.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "scenarios/scenario.h"

namespace sylva {

// what(): "<file>: <json_path>: <problem> (got <value>)", e.g.
//   scenarios/bad.json: /camera/keyframes/2/position: expected an array of 3 numbers (got "abc")
// The ": <json_path>" part is left out when the path is empty (the document itself, or a
// problem before parsing), and " (got <value>)" when there is no value to show.
class scenario_error : public std::runtime_error {
public:
    scenario_error(std::string file, std::string json_path, std::string value, std::string problem);

    const std::string& file() const { return m_file; }
    // A JSON Pointer (RFC 6901), "" for the whole document.
    const std::string& json_path() const { return m_json_path; }
    // The offending value dumped compactly (cut to about 60 characters), "nothing" for a
    // missing item, "" when there is no value (unreadable file, malformed JSON).
    const std::string& value() const { return m_value; }
    const std::string& problem() const { return m_problem; }

private:
    std::string m_file;
    std::string m_json_path;
    std::string m_value;
    std::string m_problem;
};

// A missing or unreadable file: scenario_error(file, "", "", "cannot open file: <reason>"); one
// that is not a regular file (a directory, /dev/zero, a FIFO) or is larger than
// k_max_scenario_bytes (io/input_file.h) is refused before it is read. JSON nested deeper than
// 64 levels and numbers beyond a double (1e400) are errors too.
scenario load_scenario_file(const std::filesystem::path& path);
// source_name names the text in errors and becomes scenario::source.
scenario load_scenario_text(std::string_view json_text, std::string_view source_name);
// The embedded scenarios/default.json (what `sylva play` plays without a scenario argument).
scenario load_default_scenario();

// A scenario bundled with Sylva by name ("forest" for scenarios/forest.json, embedded in the
// binary); throws scenario_error listing the bundled names when there is none of that name.
scenario load_bundled_scenario(std::string_view name);
std::vector<std::string> bundled_scenario_names();

// `s` drawn by `representation` (one of k_lod_representations): a representation other than
// "ladder" drops the file's plant budget and error threshold, which choose a ladder's rungs.
void draw_by(scenario& s, std::string representation);

// The camera path used when a scenario gives no camera keyframes: a flight across the terrain
// from its south-west to its north-east quarter, 15-25 m above the ground, over duration_s.
std::vector<scenario_camera_key> default_camera_keyframes(const terrain_settings& terrain,
                                                          double duration_s);

// The scenario as JSON text with every field written out; loading it gives back an equal
// scenario (except `source`, which names wherever the text is loaded from).
std::string scenario_to_json_text(const scenario& s);

}  // namespace sylva
