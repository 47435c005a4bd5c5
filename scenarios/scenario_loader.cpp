#include "scenarios/scenario_loader.h"

#include <set>
#include <utility>

#include "io/input_file.h"
#include "io/json_nesting.h"
#include "scenarios/embedded_files.h"
#include "scenarios/json_reader.h"
#include "scenarios/scenario_fields.h"

namespace sylva {
namespace {

constexpr std::string_view k_default_path = "scenarios/default.json";
// The format nests 4 levels deep (/camera/keyframes/0/position); 64 leaves room for any edit
// and keeps every recursive reader and printer far from the stack's end.
constexpr std::size_t k_max_scenario_depth = 64;
constexpr float k_default_fov_deg = 55.0f;  // the default camera path's

// --- text to document ----------------------------------------------------------------------

// nlohmann's message without its "[json.exception...] parse error at line L, column C: "
// prefix: the position is reported by line_and_column, the same for every library version.
std::string parse_problem(const nlohmann::json::parse_error& e) {
    const std::string what = e.what();
    const std::size_t start = what.find("parse error");
    const std::size_t colon = what.find(": ", start == std::string::npos ? 0 : start);
    return colon == std::string::npos ? what : what.substr(colon + 2);
}

// nlohmann keeps the last of two equal keys without a word; a key stated twice is almost
// always an edit gone wrong, so the second one is an error. Tracks the JSON Pointer of the
// value being parsed to name it.
class duplicate_key_check {
public:
    explicit duplicate_key_check(const std::string& file) : m_file(file) {}

    // The JSON Pointer of the value being parsed.
    std::string pointer() const {
        std::string path;
        for (const frame& f : m_stack)
            path += "/" + (f.is_object ? pointer_token(f.key) : std::to_string(f.index));
        return path;
    }

    bool operator()(nlohmann::json::parse_event_t event, const nlohmann::json& parsed) {
        using event_t = nlohmann::json::parse_event_t;
        switch (event) {
            case event_t::object_start:
                m_stack.push_back({true, {}, {}, 0});
                break;
            case event_t::array_start:
                m_stack.push_back({false, {}, {}, 0});
                break;
            case event_t::key:
                add_key(parsed.get<std::string>());
                break;
            case event_t::object_end:
            case event_t::array_end:
                m_stack.pop_back();
                end_value();
                break;
            case event_t::value:
                end_value();
                break;
        }
        return true;
    }

private:
    struct frame {
        bool is_object;
        std::set<std::string> keys;
        std::string key;
        std::size_t index;
    };

    void add_key(std::string key) {
        frame& f = m_stack.back();
        f.key = std::move(key);
        if (!f.keys.insert(f.key).second)
            throw scenario_error(m_file, pointer(), "", "duplicate key (each key may appear once)");
    }
    void end_value() {
        if (!m_stack.empty() && !m_stack.back().is_object) ++m_stack.back().index;
    }

    const std::string& m_file;
    std::vector<frame> m_stack;
};

// The token nlohmann quotes in "number overflow parsing '1e400'".
std::string quoted_token(const std::string& what) {
    const std::size_t open = what.find('\'');
    const std::size_t close = what.rfind('\'');
    return open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
}

nlohmann::json parse_document(std::string_view text, const std::string& file) {
    // Before the parser: a value nested a million deep must not reach code that recurses.
    if (const auto offset = find_nesting_beyond(text, k_max_scenario_depth))
        throw scenario_error(file, "", "",
                             "JSON nested deeper than " + std::to_string(k_max_scenario_depth) +
                                 " levels at " + line_and_column(text, *offset));
    duplicate_key_check duplicates(file);
    try {
        return nlohmann::json::parse(
            text, [&](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
                return duplicates(event, parsed);
            });
    } catch (const nlohmann::json::parse_error& e) {
        const std::size_t offset = e.byte > 0 ? e.byte - 1 : 0;  // byte is 1-based
        throw scenario_error(
            file, "", "",
            "malformed JSON at " + line_and_column(text, offset) + ": " + parse_problem(e));
    } catch (const nlohmann::json::out_of_range& e) {
        // A number beyond a double (1e400): the parser stops inside the value it was reading.
        throw scenario_error(file, duplicates.pointer(), quoted_token(e.what()),
                             "number out of range; numbers must fit a double (about 1.8e308)");
    } catch (const nlohmann::json::exception& e) {
        throw scenario_error(file, duplicates.pointer(), "", std::string("malformed JSON: ") + e.what());
    }
}

std::string stem_of(std::string_view source_name) {
    return std::filesystem::path(source_name).stem().string();
}

// A pointer through a megabyte-long key would flood the terminal: the message shows its start.
constexpr std::size_t k_max_pointer_chars = 120;

std::string what_text(const std::string& file, const std::string& json_path,
                      const std::string& value, const std::string& problem) {
    std::string text = file;
    if (!json_path.empty())
        text += ": " + (json_path.size() <= k_max_pointer_chars
                            ? json_path
                            : json_path.substr(0, k_max_pointer_chars - 3) + "...");
    text += ": " + problem;
    if (!value.empty()) text += " (got " + value + ")";
    return text;
}

}  // namespace

scenario_error::scenario_error(std::string file, std::string json_path, std::string value,
                               std::string problem)
    : std::runtime_error(what_text(file, json_path, value, problem)),
      m_file(std::move(file)),
      m_json_path(std::move(json_path)),
      m_value(std::move(value)),
      m_problem(std::move(problem)) {}

scenario load_scenario_text(std::string_view json_text, std::string_view source_name) {
    const std::string file(source_name);
    const nlohmann::json document = parse_document(json_text, file);
    scenario s;
    s.source = file;
    s.name = stem_of(source_name);
    scenario_fields().read(json_node(document, "", file), s);
    if (s.camera.keyframes.empty())
        s.camera.keyframes = default_camera_keyframes(s.terrain, double(s.frames) / s.fps);
    return s;
}

scenario load_scenario_file(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::string text;
    try {
        text = read_input_file(path, k_max_scenario_bytes);
    } catch (const input_error& e) {
        // input_error says "<path>: <problem>"; the scenario error names the file itself.
        const std::string what = e.what();
        const std::string prefix = file + ": ";
        throw scenario_error(file, "", "",
                             what.starts_with(prefix) ? what.substr(prefix.size()) : what);
    }
    return load_scenario_text(text, file);
}

scenario load_default_scenario() {
    const std::string source = "embedded:" + std::string(k_default_path);
    const auto text = embedded_file(k_default_path);
    if (!text) throw scenario_error(source, "", "", "not embedded in this build");
    return load_scenario_text(*text, source);
}

void draw_by(scenario& s, std::string representation) {
    s.lod.representation = std::move(representation);
    if (s.lod.representation != "ladder")
        s.lod.plant_budget_ms = s.lod.max_error = s.lod.gain_per_ms = 0.0;
}

std::vector<std::string> bundled_scenario_names() {
    std::vector<std::string> names;
    for (std::string_view path : embedded_file_names())
        if (path.starts_with("scenarios/") && path.ends_with(".json"))
            names.emplace_back(path.substr(10, path.size() - 15));
    return names;
}

scenario load_bundled_scenario(std::string_view name) {
    const std::string path = "scenarios/" + std::string(name) + ".json";
    const auto text = embedded_file(path);
    if (!text) {
        std::string known;
        for (const auto& n : bundled_scenario_names()) known += (known.empty() ? "" : ", ") + n;
        throw scenario_error(std::string(name), "", "",
                             "no such file, and no bundled scenario of that name (bundled: " + known + ")");
    }
    return load_scenario_text(*text, "embedded:" + path);
}

std::vector<scenario_camera_key> default_camera_keyframes(const terrain_settings& terrain,
                                                          double duration_s) {
    // South-west to north-east across the middle, looking a quarter of the terrain ahead,
    // with a rise over the centre to see across the hills.
    const double reach = 0.3 * terrain.size_m;
    const glm::dvec3 direction = glm::dvec3(1.0, 0.0, -1.0) / std::sqrt(2.0);
    const glm::dvec3 look_ahead = direction * (0.25 * terrain.size_m) + glm::dvec3(0.0, -10.0, 0.0);
    const glm::dvec3 positions[] = {{-reach, 15.0, reach}, {0.0, 25.0, 0.0}, {reach, 15.0, -reach}};
    std::vector<scenario_camera_key> keys;
    for (std::size_t i = 0; i < 3; ++i) {
        const double t = duration_s * 0.5 * double(i);
        keys.push_back({{t, positions[i], positions[i] + look_ahead, k_default_fov_deg}, true});
    }
    return keys;
}

std::string scenario_to_json_text(const scenario& s) {
    return scenario_fields().write(s).dump(2);
}

}  // namespace sylva
