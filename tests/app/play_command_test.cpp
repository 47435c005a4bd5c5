// The `sylva play` contract (issue 2): frames and metrics.json with the documented fields; a
// bad scenario gets exit code 2, one message naming file, JSON path and value, and no output.
#include <gtest/gtest.h>

#include "run_sylva.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>

namespace sylva {
namespace {

namespace fs = std::filesystem;

using result = test::command_result;

result run(const std::string& arguments) { return test::run_sylva(arguments); }

fs::path temp_dir(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("sylva_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    return dir;
}

TEST(play_command, bad_scenario_exits_2_naming_file_path_and_value_and_writes_nothing) {
    const fs::path dir = temp_dir("bad");
    fs::create_directories(dir);
    const fs::path scenario = dir / "broken.json";
    std::ofstream(scenario) << R"({"species":[{"name":"oak"}],"populations":[{"species":"elm","count":3}]})";
    const fs::path out = dir / "out";
    const result r = run("play " + scenario.string() + " --headless --out " + out.string());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("broken.json"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("/populations/0/species"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("elm"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
    fs::remove_all(dir);
}

TEST(play_command, missing_file_and_bad_option_values_exit_2) {
    EXPECT_EQ(run("play /nonexistent/scenario.json --headless").exit_code, 2);
    EXPECT_EQ(run("play --frames 0 --headless").exit_code, 2);
    EXPECT_EQ(run("play --format gif --headless").exit_code, 2);
    EXPECT_EQ(run("frobnicate").exit_code, 2);
}

// The auto ladder's options on the command line: each needs a ladder, and a threshold is not
// a budget. The message names the option, the field and the value, and exits 2 before drawing.
TEST(play_command, ladder_budget_options_without_a_ladder_or_together_exit_2_naming_them) {
    const result error = run("play tiny --headless --representation mesh_levels --max-error 0.05");
    EXPECT_EQ(error.exit_code, 2);
    EXPECT_NE(error.output.find("--max-error"), std::string::npos) << error.output;
    EXPECT_NE(error.output.find("/lod/max_error"), std::string::npos) << error.output;
    EXPECT_NE(error.output.find("--representation ladder"), std::string::npos) << error.output;
    const result both = run("play tiny --headless --representation ladder --max-error 0.05 --plant-budget-ms 10");
    EXPECT_EQ(both.exit_code, 2);
    EXPECT_NE(both.output.find("not both"), std::string::npos) << both.output;
    EXPECT_EQ(run("play tiny --headless --representation ladder --max-error 2").exit_code, 2);
    const result help = run("play --help");
    for (const char* option : {"--max-error", "--plant-budget-ms", "--target-frame-ms"})
        EXPECT_NE(help.output.find(option), std::string::npos) << option;
}

TEST(play_command, help_explains_every_option) {
    const result r = run("play --help");
    EXPECT_EQ(r.exit_code, 0);
    for (const char* option : {"--out", "--frames", "--threads", "--width", "--height", "--headless", "--format"})
        EXPECT_NE(r.output.find(option), std::string::npos) << option;
    const result v = run("view --help");
    for (const char* option : {"--exit-after", "--screenshot", "--threads", "--no-overlay"})
        EXPECT_NE(v.output.find(option), std::string::npos) << option;
}

TEST(play_command, writes_every_frame_and_a_complete_metrics_file) {
    const fs::path out = temp_dir("play");
    const std::string scenario = std::string(SYLVA_SOURCE_DIR) + "/scenarios/tiny.json";
    const result r = run("play " + scenario + " --headless --frames 2 --threads 2 --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(fs::exists(out / "frame_0000.png"));
    EXPECT_TRUE(fs::exists(out / "frame_0001.png"));
    const auto metrics = nlohmann::json::parse(std::ifstream(out / "metrics.json"));
    ASSERT_EQ(metrics["frames"].size(), 2u);
    for (const auto& f : metrics["frames"]) {
        for (const char* key : {"frame", "frame_ms", "cpu_ms", "gpu_ms", "systems", "passes", "triangles",
                                "points", "lines", "instances", "upload_bytes"})
            EXPECT_TRUE(f.contains(key)) << key;
        EXPECT_GT(f["triangles"].get<double>(), 0.0);
        EXPECT_GT(f["upload_bytes"].get<double>(), 0.0);
        EXPECT_TRUE(f["systems"].contains("cull"));
        EXPECT_TRUE(f["systems"].contains("build_draw_list"));
        EXPECT_TRUE(f["passes"].contains("shadow"));
        EXPECT_GT(f["instances"]["mesh_full"].get<int>() + f["instances"]["mesh_reduced"].get<int>() +
                      f["instances"]["mesh_far"].get<int>(), 0);
        // One count per representation Sylva can draw, and none for one it cannot draw yet: a
        // stub figure (always 0) would read as "measured, unused".
        std::vector<std::string> names;
        for (const auto& [name, count] : f["instances"].items()) names.push_back(name);
        EXPECT_EQ(names, (std::vector<std::string>{"billboard_cloud", "crossed_billboard", "eco_tile", "facing_billboard",
                                                   "lodf", "mesh_far", "mesh_full", "mesh_reduced", "points",
                                                   "shell"}));
    }
    const auto& summary = metrics["summary"];
    for (const char* key : {"median_frame_ms", "median_cpu_ms", "median_gpu_ms", "machine", "gl_renderer",
                            "gl_version", "median_systems_ms", "median_passes_ms"})
        EXPECT_TRUE(summary.contains(key)) << key;
    EXPECT_NE(summary["gl_renderer"].get<std::string>().find("llvmpipe"), std::string::npos);
    fs::remove_all(out);
}

TEST(play_command, every_shipped_scenario_plays) {
    for (const char* name : {"default", "tiny", "single_tree", "forest", "meadow", "landscape"}) {
        const fs::path out = temp_dir(std::string("library_") + name);
        const std::string scenario = std::string(SYLVA_SOURCE_DIR) + "/scenarios/" + name + ".json";
        const result r = run("play " + scenario + " --headless --frames 1 --width 160 --height 90 --out " + out.string());
        EXPECT_EQ(r.exit_code, 0) << name << ": " << r.output;
        const auto metrics = nlohmann::json::parse(std::ifstream(out / "metrics.json"));
        // Its plants drawn, on whatever rung (single_tree's auto ladder draws its oak as points
        // in this small frame).
        const auto& frame = metrics["frames"][0];
        EXPECT_GT(frame["triangles"].get<double>() + frame["points"].get<double>() +
                      frame["lines"].get<double>(),
                  0.0)
            << name;
        fs::remove_all(out);
    }
}

TEST(play_command, reference_and_full_geometry_draw_every_plant_at_full_detail) {
    const std::string scenario = std::string(SYLVA_SOURCE_DIR) + "/scenarios/tiny.json";
    for (const char* mode : {"--reference", "--full-geometry"}) {
        const fs::path out = temp_dir(std::string("mode") + (mode + 2));
        const result r = run("play " + scenario + " --headless --frames 1 " + mode + " --out " + out.string());
        ASSERT_EQ(r.exit_code, 0) << r.output;
        const auto metrics = nlohmann::json::parse(std::ifstream(out / "metrics.json"));
        const auto& summary = metrics["summary"];
        EXPECT_EQ(summary["samples_per_pixel"].get<int>(), std::string(mode) == "--reference" ? 9 : 1);
        EXPECT_EQ(summary["width"].get<int>(), 160);  // the reference is resolved to the scenario size
        const auto& instances = metrics["frames"][0]["instances"];
        EXPECT_EQ(instances["mesh_reduced"].get<int>() + instances["mesh_far"].get<int>(), 0) << mode;
        EXPECT_GT(instances["mesh_full"].get<int>(), 0) << mode;
        fs::remove_all(out);
    }
    EXPECT_EQ(run("play " + scenario + " --reference --full-geometry").exit_code, 2);
}

TEST(play_command, exr_frames_are_written_through_openimageio) {
    const fs::path out = temp_dir("exr");
    const std::string scenario = std::string(SYLVA_SOURCE_DIR) + "/scenarios/tiny.json";
    const result r = run("play " + scenario +
                         " --representation mesh_levels --headless --frames 1 --format exr --out " +
                         out.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::ifstream exr(out / "frame_0000.exr", std::ios::binary);
    char magic[4] = {};
    exr.read(magic, 4);
    // OpenEXR magic number 20000630 (0x01312f76), little-endian.
    EXPECT_EQ(std::string(magic, 4), std::string("\x76\x2f\x31\x01", 4));
    fs::remove_all(out);
}

}  // namespace
}  // namespace sylva

namespace sylva {
namespace {

// FNV-1a 64, as models/cache/bake_cache.h checksums entries (hand-written here so the test does not
// trust the code under test to make its fixture).
std::uint64_t fnv1a_64(const std::string& bytes) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : bytes) h = (h ^ std::uint8_t(c)) * 0x100000001b3ULL;
    return h;
}

// A cache entry whose checksum is right but whose payload is not three positive costs.
std::string entry_holding(const std::string& payload) {
    std::string entry = "SYLVACE1";
    const std::uint64_t size = payload.size(), sum = fnv1a_64(payload);
    entry.append(reinterpret_cast<const char*>(&size), 8);
    entry.append(reinterpret_cast<const char*>(&sum), 8);
    return entry + payload;
}

// Issue 19: a damaged primitive_costs entry made every later play fail. The device's cost
// model (app/device_costs.h) is now reported and measured again when its entry is damaged: a
// truncation or a bit flip the cache's checksum catches (bake_cache tests), or a model that
// makes no sense under a valid checksum, which its reader must refuse. A calibration takes about
// 30 s here, so the test damages once and reads the rebuilt entry back with `calibrate`.
TEST(play_command, a_damaged_primitive_cost_model_entry_is_rebuilt_not_fatal) {
    const fs::path dir = temp_dir("costs");
    const std::string cache = "SYLVA_CACHE_DIR=" + (dir / "cache").string() + " ";
    const std::string play = cache + test::sylva_binary() +
                             " play tiny --headless --frames 1 --width 64 --height 64 --representation "
                             "points_lines --out " + (dir / "out").string();
    ASSERT_EQ(test::run_command(play).exit_code, 0);
    const fs::path costs = dir / "cache" / "primitive_cost_model";
    ASSERT_TRUE(fs::exists(costs)) << "points_lines must have measured and cached its costs";
    // Status 0 (a model) and six cost lines, the first a = -1 µs: no device costs less than nothing.
    std::string nonsense(1, '\0');
    const double lines[12] = {-1.0, 0.0, 1.0, 0.01, 1.0, 0.01, 1.0, 0.01, 1.0, 0.0, 1.0, 0.01};
    nonsense.append(reinterpret_cast<const char*>(lines), sizeof(lines));
    for (const auto& entry : fs::directory_iterator(costs))
        std::ofstream(entry.path(), std::ios::binary) << entry_holding(nonsense);
    const result r = test::run_command(play);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("primitive_cost_model"), std::string::npos) << "the damage must be reported:\n" << r.output;
    EXPECT_NE(r.output.find("rebuilding it"), std::string::npos) << r.output;
    // The rebuilt entry is whole: the same device (64x64) reads it back without measuring again.
    const result again = test::run_command(cache + test::sylva_binary() + " calibrate --width 64 --height 64");
    EXPECT_EQ(again.exit_code, 0) << again.output;
    EXPECT_NE(again.output.find("from the bake cache"), std::string::npos) << again.output;
    EXPECT_EQ(again.output.find("rebuilding"), std::string::npos) << "rebuilt once:\n" << again.output;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
