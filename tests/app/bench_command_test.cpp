// The `sylva bench` command line: outputs, the configuration list and bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../gl/gl_test_support.h"
#include "run_sylva.h"

namespace sylva {
namespace {

TEST(bench_command, lists_its_configurations) {
    const auto r = test::run_sylva("bench --list");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    for (const char* name : {"reference", "brute_force", "baseline", "mesh_lod", "crossed_billboard_only"})
        EXPECT_NE(r.output.find(name), std::string::npos) << name;
}

TEST(bench_command, rejects_an_unknown_configuration_by_name) {
    SYLVA_REQUIRE_GL();
    const auto dir = std::filesystem::temp_directory_path() / "sylva_bench_bad";
    const auto r = test::run_sylva("bench tiny --frames 2 --only brute_force,nonsense --out " + dir.string());
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("no configuration named 'nonsense'"), std::string::npos) << r.output;
}

TEST(bench_command, writes_table_plot_and_summary) {
    SYLVA_REQUIRE_GL();
    const auto dir = std::filesystem::temp_directory_path() / "sylva_bench_command";
    std::filesystem::remove_all(dir);
    const auto r = test::run_sylva("bench tiny --frames 3 --only brute_force,baseline --out " + dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const char* file : {"bench.json", "bench.csv", "bench.svg", "summary.md"})
        EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
    std::ifstream in(dir / "bench.json");
    const auto json = nlohmann::json::parse(in);
    EXPECT_EQ(json.at("scenario"), "tiny");
    EXPECT_TRUE(json.contains("machine"));
    ASSERT_EQ(json.at("configurations").size(), 2u);
    const auto& brute = json.at("configurations").at(0);
    EXPECT_EQ(brute.at("name"), "brute_force");
    for (const char* key : {"frame_ms", "cpu_ms", "gpu_ms", "primitives", "upload_bytes", "peak_memory_mb", "error"})
        EXPECT_TRUE(brute.contains(key)) << key;
    for (const char* key : {"psnr", "ssim", "perceptual", "coverage_iou", "popping", "lighting_jump"})
        EXPECT_TRUE(brute.at("error").contains(key)) << key;
    EXPECT_GT(brute.at("frame_ms").at("median").get<double>(), 0.0);
    EXPECT_GT(brute.at("peak_memory_mb").get<double>(), 1.0);
    EXPECT_EQ(json.at("configurations").at(1).at("name"), "baseline");
    // The stdout table has a row per configuration, and the verdict follows it.
    EXPECT_NE(r.output.find("baseline"), std::string::npos);
    // Only the instance counts of representations that exist (no stub figures).
    for (const auto& c : json.at("configurations"))
        for (const char* stub : {"instances_lines", "instances_foliage_clusters"})
            EXPECT_FALSE(c.at("primitives").contains(stub)) << stub;
}

// A metric that cannot see reports n/a: shells blended straight into the frame write no plant
// IDs, so their coverage IoU is not measured, where the same shells in the half-size layer are.
TEST(bench_command, coverage_of_shells_that_write_no_ids_is_not_measured) {
    SYLVA_REQUIRE_GL();
    const auto dir = std::filesystem::temp_directory_path() / "sylva_bench_shell_ids";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto path = dir / "shrubs.json";
    std::ofstream(path) << R"({"name": "shrubs", "seed": 9,
 "terrain": {"size_m": 96, "resolution": 33, "height_m": 24, "octaves": 2, "frequency": 0.03},
 "wang_tiles": {"tile_size_m": 16, "colours": 2},
 "species": [{"name": "bush", "generator": "shrub", "height_m": 1.6}],
 "populations": [{"species": "bush", "count": 300, "min_spacing_m": 1.5, "placement": "wang_tiles",
                  "area": [-30, -30, 30, 30]}],
 "camera": {"keyframes": [{"t": 0, "position": [-42, 26, -42], "target": [0, 0, 0], "fov_deg": 50}]},
 "lod": {"representation": "ladder", "ladder": [{"rung": "mesh_full"}, {"rung": "shell", "below_px": 1000}]}})";
    const auto r = test::run_sylva("bench " + path.string() +
                                   " --frames 1 --width 96 --height 54 --only ladder,ladder_shells_full_resolution --out " +
                                   (dir / "out").string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::ifstream in(dir / "out" / "bench.json");
    const auto json = nlohmann::json::parse(in);
    ASSERT_EQ(json.at("configurations").size(), 2u);
    for (const auto& c : json.at("configurations")) {
        const auto& iou = c.at("error").at("coverage_iou");
        if (c.at("name") == "ladder") {
            ASSERT_TRUE(iou.is_number()) << iou;
            EXPECT_GT(iou.get<double>(), 0.2);
        } else {
            EXPECT_TRUE(iou.is_null()) << c.at("name") << ": " << iou;
        }
    }
}

// The representation options are measured, not ignored: each adds the configuration `play` would
// draw with them (issue 18 item 7), named as --list names it.
TEST(bench_command, representation_options_add_the_configuration_play_would_draw) {
    SYLVA_REQUIRE_GL();
    const auto dir = std::filesystem::temp_directory_path() / "sylva_bench_options";
    std::filesystem::remove_all(dir);
    const auto r = test::run_sylva("bench tiny --frames 2 --only baseline --representation points_lines "
                                   "--sample-distance 3 --splats opaque --out " + dir.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::ifstream in(dir / "bench.json");
    const auto json = nlohmann::json::parse(in);
    std::vector<std::string> names;
    for (const auto& c : json.at("configurations")) names.push_back(c.at("name"));
    EXPECT_EQ(names, (std::vector<std::string>{"baseline", "points_lines_d3_opaque"}));
    const auto& extra = json.at("configurations").at(1);
    EXPECT_GT(extra.at("primitives").at("points").get<double>(), 0.0);
    EXPECT_NE(extra.at("description").get<std::string>().find("from the command line"), std::string::npos);
}

TEST(bench_command, options_that_do_not_apply_are_refused_not_ignored) {
    // Over mesh levels d' and budgets mean nothing.
    for (const char* option : {"--sample-distance 2", "--splats soft", "--primitive-budget 1000", "--target-frame-ms 30"}) {
        const auto dir = std::filesystem::temp_directory_path() / "sylva_bench_refused";
        std::filesystem::remove_all(dir);
        const auto r = test::run_sylva(
            std::string("bench tiny --representation mesh_levels --frames 1 --only baseline ") +
            option + " --out " + dir.string());
        EXPECT_EQ(r.exit_code, 2) << option << ": " << r.output;
        const std::string name = std::string(option).substr(0, std::string(option).find(' '));
        EXPECT_NE(r.output.find(name + " sets points and lines"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("add --representation points_lines"), std::string::npos) << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "bench.json"));
    }
}

}  // namespace
}  // namespace sylva
