// The hostile corpus (issue 19): scenarios, glTF files and command lines a careless or
// malicious user could hand Sylva. Each must end with the documented exit code and a message
// naming the file, field or value; never a crash, a hang (every run is under a timeout), a read
// outside the model's folder, or a silent success. Run the corpus against another build with
// SYLVA_TEST_BINARY=/path/to/sylva (tests/app/run_sylva.h).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "hostile_inputs.h"
#include "run_sylva.h"
#include "tests/sanitized.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;
using test::make_glb;
using test::make_triangle_buffer;
using test::triangle_json;
using test::write_file;

// A file outside every model folder whose name, size or content must never appear in output.
constexpr std::size_t k_secret_bytes = 31337;
const std::string k_secret_text = "TOPSECRET-hostile-corpus";

struct hostile_case {
    std::string name;
    std::function<void(const fs::path& dir)> setup;
    std::string arguments;  // "{dir}" is the case's folder
    int exit_code = 2;
    std::vector<std::string> expected;  // each must appear in the output
    std::string limits = "";            // shell commands before exec (ulimit)
    int timeout_s = 60;
};

// gtest prints a case by its name, not as a dump of its bytes.
void PrintTo(const hostile_case& c, std::ostream* out) { *out << c.name; }

std::string replace_dir(std::string text, const fs::path& dir) {
    for (std::size_t at; (at = text.find("{dir}")) != std::string::npos;) text.replace(at, 5, dir.string());
    return text;
}

// A minimal valid scenario: one generated species, one plant, 32x18, one frame; `fields` are
// more members (each ending in a comma) and `species_extra`/`population_extra` go inside.
std::string scenario_json(const std::string& fields = "", const std::string& species_extra = "",
                          const std::string& population_extra = "") {
    return "{" + fields + R"("resolution":[32,18],"frames":1,"species":[{"name":"a")" + species_extra +
           R"(}],"populations":[{"species":"a","count":1)" + population_extra + "}]}";
}

void write_scenario(const fs::path& dir, const std::string& text) { write_file(dir / "s.json", text); }

std::string deep(std::size_t levels, const std::string& open, const std::string& close,
                 const std::string& inner = "") {
    std::string text;
    text.reserve(levels * (open.size() + close.size()) + inner.size());
    for (std::size_t i = 0; i < levels; ++i) text += open;
    text += inner;
    for (std::size_t i = 0; i < levels; ++i) text += close;
    return text;
}

void write_glb_file(const fs::path& path, const std::string& json) {
    write_file(path, make_glb(json, make_triangle_buffer().bytes));
}

// The triangle as .gltf with its buffer in "tri.bin" next to it, the JSON changed by `edit`.
void write_gltf_with_uri(const fs::path& dir, const std::string& uri) {
    fs::create_directories(dir / "model");
    const auto bin = make_triangle_buffer().bytes;
    write_file(dir / "model" / "tri.bin", std::string(bin.begin(), bin.end()));
    write_file(dir / "model" / "tree.gltf", triangle_json(uri));
}

const std::string k_play = "play {dir}/s.json --headless --frames 1 --out {dir}/out";

std::vector<hostile_case> hostile_cases() {
    std::vector<hostile_case> cases;
    auto scenario_case = [&](std::string name, std::string text, std::vector<std::string> expected) {
        cases.push_back({std::move(name), [text](const fs::path& d) { write_scenario(d, text); }, k_play, 2,
                         std::move(expected)});
    };
    // --- scenarios: numbers, nesting, size, kinds of file --------------------------------------
    scenario_case("number_beyond_double", scenario_json(R"("seed":1e400,)"),
                  {"s.json", "/seed", "1e400", "out of range"});
    scenario_case("negative_number_beyond_double", scenario_json(R"("terrain":{"size_m":-1e400},)"),
                  {"/terrain/size_m", "out of range"});
    scenario_case("integer_of_400_digits", scenario_json("\"frames\":" + std::string(400, '9') + ","),
                  {"/frames", "out of range"});
    scenario_case("array_nested_a_million_deep", scenario_json("\"name\":" + deep(1000000, "[", "]") + ","),
                  {"s.json", "nested deeper than 64"});
    scenario_case("object_nested_100000_deep", scenario_json("\"name\":" + deep(100000, "{\"a\":", "}", "1") + ","),
                  {"nested deeper than 64"});
    scenario_case("unclosed_million_brackets", deep(1000000, "[", ""), {"s.json", "nested deeper than 64"});
    scenario_case("nesting_within_limit_but_wrong_type", scenario_json("\"name\":" + deep(60, "[", "]") + ","),
                  {"/name", "expected a string", "[[[["});
    scenario_case("empty_file", "", {"s.json", "malformed JSON"});
    scenario_case("binary_garbage", std::string("\x00\xff\xfe\x89PNG\r\n\x1a\n\x00\x01", 12),
                  {"s.json", "malformed JSON"});
    scenario_case("nan_literal", scenario_json(R"("seed":NaN,)"), {"s.json", "malformed JSON"});
    scenario_case("duplicate_key", scenario_json(R"("frames":2,"frames":3,)"), {"/frames", "duplicate key"});
    scenario_case("string_for_a_number", scenario_json(R"("fps":"fast",)"), {"/fps", "expected a number", "fast"});
    scenario_case("negative_count", R"({"species":[{"name":"a"}],"populations":[{"species":"a","count":-5}]})",
                  {"/populations/0/count", "-5"});
    scenario_case("megabyte_unknown_key", scenario_json("\"" + std::string(1 << 20, 'k') + "\":1,"),
                  {"s.json", "unknown field", "kkk..."});
    scenario_case("resolution_a_billion", R"({"resolution":[1000000000,18],"species":[{"name":"a"}],)"
                                          R"("populations":[{"species":"a","count":1}]})",
                  {"/resolution/0", "out of range"});
    cases.push_back({"scenario_is_dev_zero", {}, "play /dev/zero --headless --out {dir}/out", 2,
                     {"/dev/zero", "a character device"}});
    cases.push_back({"scenario_is_a_directory", [](const fs::path& d) { fs::create_directories(d / "s.json"); },
                     k_play, 2, {"s.json", "a directory"}});
    cases.push_back({"scenario_is_a_fifo", [](const fs::path& d) { ::mkfifo((d / "s.json").c_str(), 0600); },
                     k_play, 2, {"s.json", "FIFO"}, "", 20});
    cases.push_back({"scenario_of_17_megabytes",
                     [](const fs::path& d) { write_scenario(d, std::string(17 << 20, ' ')); }, k_play, 2,
                     {"s.json", "16 MB limit"}});
    // --- files a scenario names: exit 2 with the field, before anything is written --------------
    cases.push_back({"heightmap_is_a_directory",
                     [](const fs::path& d) {
                         fs::create_directories(d / "hm.png");
                         write_scenario(d, scenario_json(R"("terrain":{"heightmap":"hm.png"},)"));
                     },
                     k_play, 2, {"/terrain/heightmap", "a directory"}});
    cases.push_back({"heightmap_is_text",
                     [](const fs::path& d) {
                         write_file(d / "hm.png", "not an image at all");
                         write_scenario(d, scenario_json(R"("terrain":{"heightmap":"hm.png"},)"));
                     },
                     k_play, 2, {"s.json", "/terrain/heightmap", "hm.png"}});
    cases.push_back({"heightmap_header_claims_30000_squared",
                     [](const fs::path& d) {
                         write_file(d / "hm.png", test::png_header_claiming(30000, 30000));
                         write_scenario(d, scenario_json(R"("terrain":{"heightmap":"hm.png"},)"));
                     },
                     k_play, 2, {"/terrain/heightmap", "30000x30000"}, "ulimit -v 3000000;"});
    cases.push_back({"density_map_is_text",
                     [](const fs::path& d) {
                         write_file(d / "density.png", "garbage");
                         write_scenario(d, scenario_json("", "", R"(,"density_map":"density.png")"));
                     },
                     k_play, 2, {"/populations/0/density_map", "density.png"}});
    cases.push_back({"environment_map_is_text",
                     [](const fs::path& d) {
                         write_file(d / "sky.hdr", "garbage");
                         write_scenario(d, scenario_json(R"("environment":{"map":"sky.hdr"},)"));
                     },
                     k_play, 2, {"/environment/map", "sky.hdr"}});
    cases.push_back({"species_model_is_garbage",
                     [](const fs::path& d) {
                         write_file(d / "tree.glb", std::string(64, 'x'));
                         write_scenario(d, scenario_json("", R"(,"model":"tree.glb")"));
                     },
                     k_play, 2, {"/species/0/model", "tree.glb", "glTF"}});
    cases.push_back({"species_model_is_dev_zero",
                     [](const fs::path& d) {
                         fs::create_symlink("/dev/zero", d / "tree.glb");
                         write_scenario(d, scenario_json("", R"(,"model":"tree.glb")"));
                     },
                     k_play, 2, {"/species/0/model", "a character device"}});
    cases.push_back({"species_model_reads_outside_its_folder",
                     [](const fs::path& d) {
                         write_glb_file(d / "models" / "tree.glb", triangle_json("../secret.bin"));
                         write_scenario(d, scenario_json("", R"(,"model":"models/tree.glb")"));
                     },
                     k_play, 2, {"/species/0/model", "'../secret.bin'", "outside the model's folder"}});
    // --- command lines ---------------------------------------------------------------------------
    cases.push_back({"stress_with_99999_threads", {}, "stress --threads 99999", 2, {"--threads"}});
    cases.push_back({"play_with_negative_threads", {}, "play --threads -1 --headless --out {dir}/out", 2,
                     {"--threads"}});
    cases.push_back({"play_with_absurd_frames", {}, "play --frames 99999999999 --headless --out {dir}/out", 2,
                     {"--frames"}});
    cases.push_back({"play_with_text_width", {}, "play --width abc --headless --out {dir}/out", 2, {"--width"}});
    cases.push_back({"bench_of_a_fifo", [](const fs::path& d) { ::mkfifo((d / "s.json").c_str(), 0600); },
                     "bench {dir}/s.json --out {dir}/out", 2, {"s.json", "FIFO"}, "", 20});
    // --- outputs: refused or failing writes are errors naming the path ------------------------
    cases.push_back({"plant_out_is_a_directory", [](const fs::path& d) { fs::create_directories(d / "x.glb"); },
                     "plant grass --texture-size 16 --out {dir}/x.glb", 1, {"x.glb", "a directory"}});
    cases.push_back({"plant_out_is_dev_full", {}, "plant grass --texture-size 16 --out /dev/full", 1,
                     {"/dev/full", "not a regular file"}});
    cases.push_back({"plant_on_a_full_disk", {}, "plant grass --texture-size 16 --out {dir}/x.glb", 1,
                     {"x.glb", "File too large"}, "ulimit -f 8;"});
    cases.push_back({"export_cloud_on_a_full_disk", {}, "export-cloud grass --texture-size 16 --out {dir}/c.glb", 1,
                     {"c.glb", "File too large"}, "ulimit -f 8;"});
    cases.push_back({"play_on_a_full_disk",
                     {},
                     "play tiny --representation mesh_levels --headless --frames 2 --width 32 "
                     "--height 18 --out {dir}/out",
                     1,
                     {"frame_0000.png", "File too large"},
                     "ulimit -f 0;"});
    // --- glTF: containers, nesting, confinement, lies about sizes ------------------------------
    auto inspect_case = [&](std::string name, std::function<void(const fs::path&)> setup,
                            std::vector<std::string> expected, std::string file = "model/tree.glb",
                            std::string limits = "") {
        cases.push_back({std::move(name), std::move(setup), "inspect {dir}/" + file, 2, std::move(expected),
                         std::move(limits)});
    };
    inspect_case("glb_json_nested_100000_deep",
                 [](const fs::path& d) {
                     write_glb_file(d / "model/tree.glb",
                                    triangle_json("", 3, ",\"extras\":" + deep(100000, "[", "]")));
                 },
                 {"tree.glb", "nests deeper than 256"});
    inspect_case("gltf_json_nested_100000_deep",
                 [](const fs::path& d) {
                     write_gltf_with_uri(d, "tri.bin");
                     write_file(d / "model/tree.gltf",
                                triangle_json("tri.bin", 3, ",\"extras\":" + deep(100000, "{\"a\":", "}", "0")));
                 },
                 {"tree.gltf", "nests deeper than 256"}, "model/tree.gltf");
    for (const auto& [name, uri, words] : std::vector<std::tuple<std::string, std::string, std::string>>{
             {"buffer_uri_parent", "../secret.bin", "outside the model's folder"},
             {"buffer_uri_percent_encoded_parent", "%2e%2e/secret.bin", "outside the model's folder"},
             {"buffer_uri_deep_parent", "sub/../../../../../../../../etc/passwd", "outside the model's folder"},
             {"buffer_uri_absolute", "/etc/passwd", "absolute path"},
             {"buffer_uri_file_scheme", "file:///etc/passwd", "has a scheme"},
             {"buffer_uri_http_scheme", "http://example.invalid/tri.bin", "has a scheme"},
             {"buffer_uri_symlink_out", "link.bin", "outside the model's folder"}}) {
        inspect_case(name,
                     [uri = uri](const fs::path& d) {
                         write_gltf_with_uri(d, uri);
                         fs::create_symlink(d / "secret.bin", d / "model/link.bin");
                     },
                     {"tree.gltf", "'" + uri + "'", words}, "model/tree.gltf");
    }
    inspect_case("image_uri_outside",
                 [](const fs::path& d) {
                     write_gltf_with_uri(d, "tri.bin");
                     write_file(d / "model/tree.gltf",
                                triangle_json("tri.bin", 3, R"(,"images":[{"uri":"../secret.bin"}])"));
                 },
                 {"image 0", "'../secret.bin'", "outside the model's folder"}, "model/tree.gltf");
    inspect_case("index_0xFFFFFFF0",
                 [](const fs::path& d) {
                     write_file(d / "model/tree.glb",
                                make_glb(triangle_json(), make_triangle_buffer(0, 1, 0xFFFFFFF0u).bytes));
                 },
                 {"4294967280", "past the last vertex"});
    inspect_case("count_of_750_million_in_2_kilobytes",
                 [](const fs::path& d) { write_glb_file(d / "model/tree.glb", triangle_json("", 750000000)); },
                 {"750000000 elements", "past the end of its buffer"}, "model/tree.glb", "ulimit -v 1500000;");
    inspect_case("texture_header_claims_30000_squared",
                 [](const fs::path& d) {
                     const std::string png = test::png_header_claiming(30000, 30000);
                     write_file(d / "model/big.png", png);
                     write_gltf_with_uri(d, "tri.bin");
                     write_file(d / "model/tree.gltf",
                                triangle_json("tri.bin", 3,
                                              R"(,"images":[{"uri":"big.png"}],"textures":[{"source":0}])"));
                 },
                 {"30000x30000"}, "model/tree.gltf", "ulimit -v 1500000;");
    inspect_case("glb_header_claims_more_than_the_file",
                 [](const fs::path& d) {
                     std::string glb = make_glb(triangle_json(), make_triangle_buffer().bytes);
                     glb.resize(glb.size() - 20);
                     write_file(d / "model/tree.glb", glb);
                 },
                 {"tree.glb", "truncated"});
    inspect_case("glb_version_1",
                 [](const fs::path& d) {
                     std::string glb = make_glb(triangle_json(), make_triangle_buffer().bytes);
                     glb[4] = 1;
                     write_file(d / "model/tree.glb", glb);
                 },
                 {"tree.glb", "version 1"});
    inspect_case("glb_json_chunk_past_the_end",
                 [](const fs::path& d) {
                     std::string glb = make_glb(triangle_json(), make_triangle_buffer().bytes);
                     glb[14] = char(0x7F);  // JSON chunk length += 8 MB
                     write_file(d / "model/tree.glb", glb);
                 },
                 {"tree.glb", "JSON chunk"});
    inspect_case("empty_glb", [](const fs::path& d) { write_file(d / "model/tree.glb", ""); },
                 {"tree.glb", "too short"});
    inspect_case("glb_is_a_directory", [](const fs::path& d) { fs::create_directories(d / "model/tree.glb"); },
                 {"tree.glb", "a directory"});
    inspect_case("accessor_offset_overflows",
                 [](const fs::path& d) {
                     std::string json = triangle_json();
                     json.replace(json.find(R"("bufferView":1,)"), 15,
                                  R"("bufferView":1,"byteOffset":18446744073709551600,)");
                     write_glb_file(d / "model/tree.glb", json);
                 },
                 {"tree.glb"});
    inspect_case("stride_shorter_than_an_element",
                 [](const fs::path& d) {
                     std::string json = triangle_json();
                     json.replace(json.find(R"("byteOffset":12,"byteLength":36)"), 31,
                                  R"("byteOffset":12,"byteLength":36,"byteStride":4)");
                     write_glb_file(d / "model/tree.glb", json);
                 },
                 {"tree.glb"});
    inspect_case("node_cycle",
                 [](const fs::path& d) {
                     std::string json = triangle_json();
                     json.replace(json.find(R"("nodes":[{"mesh":0}])"), 20,
                                  R"("nodes":[{"mesh":0,"children":[1]},{"children":[0]}])");
                     write_glb_file(d / "model/tree.glb", json);
                 },
                 {"tree.glb", "cycle"});
    inspect_case("inspect_a_missing_file", {}, {"absent.glb", "no such file"}, "model/absent.glb");
    cases.push_back({"bake_a_garbage_model", [](const fs::path& d) { write_file(d / "tree.glb", "garbage!"); },
                     "bake {dir}/tree.glb --cache {dir}/cache", 2, {"tree.glb"}});
    cases.push_back({"export_cloud_of_a_garbage_model",
                     [](const fs::path& d) { write_file(d / "tree.glb", "garbage!"); },
                     "export-cloud {dir}/tree.glb --out {dir}/c.glb", 2, {"tree.glb"}});
    return cases;
}

class hostile_corpus : public ::testing::TestWithParam<hostile_case> {};

TEST_P(hostile_corpus, ends_with_a_clear_error) {
    const hostile_case& c = GetParam();
    const fs::path dir = test::fresh_temp_dir("hostile_" + c.name);
    write_file(dir / "secret.bin", k_secret_text + std::string(k_secret_bytes - k_secret_text.size(), '.'));
    if (c.setup) c.setup(dir);
    // Under ASan the binary reserves terabytes of address space: no `ulimit -v` then.
    const bool bounds_memory = c.limits.find("ulimit -v") != std::string::npos;
    const std::string limits = bounds_memory && testing::k_sanitized ? "" : c.limits;
    const std::string command = "cd " + dir.string() + " && timeout -k 5 " + std::to_string(c.timeout_s) +
                                " sh -c 'trap \"\" XFSZ; " + limits + " exec " + test::sylva_binary() + " " +
                                replace_dir(c.arguments, dir) + "'";
    const test::command_result r = test::run_command(command);
    EXPECT_EQ(r.exit_code, c.exit_code) << "124: hung; 128+n: killed by signal n\n" << r.output.substr(0, 4000);
    for (const std::string& word : c.expected)
        EXPECT_NE(r.output.find(replace_dir(word, dir)), std::string::npos)
            << "missing \"" << word << "\" in:\n" << r.output.substr(0, 4000);
    EXPECT_EQ(r.output.find(std::to_string(k_secret_bytes)), std::string::npos) << "leaks the secret's size";
    EXPECT_EQ(r.output.find(k_secret_text), std::string::npos) << "leaks the secret";
    EXPECT_EQ(r.output.find("wrote"), std::string::npos) << "claims success:\n" << r.output.substr(0, 4000);
    EXPECT_LT(r.output.size(), 20000u) << "one clear error, not a flood";
    if (c.exit_code == 2) {
        EXPECT_FALSE(fs::exists(dir / "out")) << "bad input must write nothing";
    }
    for (const auto& entry : fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied))
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos)
            << "left a temporary file: " << entry.path();
    fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(issue19, hostile_corpus, ::testing::ValuesIn(hostile_cases()),
                         [](const ::testing::TestParamInfo<hostile_case>& param) { return param.param.name; });

// The corpus's own control: the triangle every glTF case breaks is a model Sylva reads, so each
// case fails for the reason it names and not because the template was broken.
TEST(hostile_corpus_control, the_unbroken_triangle_imports) {
    const fs::path dir = test::fresh_temp_dir("hostile_control");
    write_glb_file(dir / "tree.glb", triangle_json());
    write_gltf_with_uri(dir, "tri.bin");
    const auto glb = test::run_sylva("inspect " + (dir / "tree.glb").string());
    EXPECT_EQ(glb.exit_code, 0) << glb.output;
    const auto gltf = test::run_sylva("inspect " + (dir / "model/tree.gltf").string());
    EXPECT_EQ(gltf.exit_code, 0) << gltf.output;
    fs::remove_all(dir);
}

TEST(hostile_corpus_control, holds_at_least_40_cases) { EXPECT_GE(hostile_cases().size(), 40u); }

}  // namespace
}  // namespace sylva
