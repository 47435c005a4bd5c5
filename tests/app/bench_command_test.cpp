// The `sylva bench` command line: outputs, the configuration list and bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

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
    // The stdout table has a row per configuration.
    EXPECT_NE(r.output.find("baseline"), std::string::npos);
}

}  // namespace
}  // namespace sylva
