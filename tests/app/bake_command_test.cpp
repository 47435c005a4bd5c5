// `sylva bake`: the first run bakes every species into the cache, the second finds them all; for
// a scenario playing the auto ladder it also measures the rung tables, so its play measures none,
// and prints them when asked.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "models/cache/bake_cache.h"
#include "run_sylva.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

std::pair<int, std::string> run(const std::string& arguments) {
    const test::command_result r = test::run_sylva(arguments);
    return {r.exit_code, r.output};
}

TEST(bake_command, bakes_once_then_serves_every_species_from_the_cache) {
    const fs::path cache = fs::temp_directory_path() / ("sylva_bake_test_" + std::to_string(::getpid()));
    fs::remove_all(cache);
    const std::string scenario = std::string(SYLVA_SOURCE_DIR) + "/scenarios/tiny.json";
    const auto first = run("bake " + scenario + " --species-only --cache " + cache.string());
    ASSERT_EQ(first.first, 0) << first.second;
    EXPECT_NE(first.second.find("2 species (model, crossed billboard, points and lines, billboard cloud each): 0 cache entries reused, 8 baked"), std::string::npos) << first.second;
    const auto second = run("bake " + scenario + " --species-only --cache " + cache.string());
    EXPECT_NE(second.second.find("2 species (model, crossed billboard, points and lines, billboard cloud each): 8 cache entries reused, 0 baked"), std::string::npos) << second.second;
    const auto forced =
        run("bake " + scenario + " --species-only --force --cache " + cache.string());
    EXPECT_NE(forced.second.find("0 cache entries reused, 8 baked"), std::string::npos) << forced.second;
    fs::remove_all(cache);
}

// The device's calibration (about a minute on llvmpipe, kept in the cache by device) from the
// suite's own cache when it has one, so a fresh cache measures only the scenario's tables.
void copy_device_calibration(const fs::path& to) {
    const fs::path from = bake_cache().root();  // $SYLVA_CACHE_DIR, else the user's
    std::error_code ec;
    fs::create_directories(to, ec);
    for (const char* kind : {"primitive_cost_model", "shader_work_costs"})
        fs::copy(from / kind, to / kind, fs::copy_options::recursive, ec);  // absent: measured
}

// tiny's spruce alone on a two-rung auto ladder: its tables take seconds (tiny's whole ladder
// about 100 s).
TEST(bake_command, a_scenario_s_auto_ladder_tables_are_measured_so_its_play_measures_none) {
    const fs::path dir = test::fresh_temp_dir("bake_ladder");
    copy_device_calibration(dir / "cache");
    nlohmann::json s = nlohmann::json::parse(
        std::ifstream(std::string(SYLVA_SOURCE_DIR) + "/scenarios/tiny.json"));
    s["name"] = "bake_ladder";
    s["frames"] = 1;
    s["species"] = nlohmann::json::array({s["species"][1]});
    s["populations"] = nlohmann::json::array({s["populations"][1]});
    s["lod"] = {
        {"representation", "ladder"},
        {"plant_budget_ms", 30},
        {"ladder", nlohmann::json::array({{{"rung", "mesh_full"}},
                                          {{"rung", "crossed_billboard"}, {"below_px", 40}}})}};
    const fs::path scenario = dir / "bake_ladder.json";
    std::ofstream(scenario) << s.dump(2);
    const std::string cache = " --cache " + (dir / "cache").string();
    const auto baked = run("bake " + scenario.string() + cache);
    ASSERT_EQ(baked.first, 0) << baked.second;
    EXPECT_NE(baked.second.find("measuring the rung tables of spruce"), std::string::npos)
        << baked.second;
    // Again, printing what the solver chooses from: the tables come from the cache.
    const auto again = run("bake " + scenario.string() + cache + " --print-tables");
    EXPECT_NE(again.second.find(", 0 made,"), std::string::npos) << again.second;
    EXPECT_NE(again.second.find("spruce: error per plant pixel"), std::string::npos)
        << again.second;
    EXPECT_NE(again.second.find("\nmesh_full          error"), std::string::npos) << again.second;
    EXPECT_NE(again.second.find("\ncrossed_billboard  error"), std::string::npos) << again.second;
    const test::command_result played = test::run_command(
        "SYLVA_CACHE_DIR=" + (dir / "cache").string() + " " + test::sylva_binary() + " play " +
        scenario.string() + " --headless --out " + (dir / "out").string());
    ASSERT_EQ(played.exit_code, 0) << played.output;
    EXPECT_EQ(played.output.find("measuring the rung tables"), std::string::npos) << played.output;
    fs::remove_all(dir);
}

TEST(bake_command, bad_input_exits_2_naming_the_file) {
    const auto missing = run("bake /nonexistent/forest.json");
    EXPECT_EQ(missing.first, 2);
    EXPECT_NE(missing.second.find("/nonexistent/forest.json"), std::string::npos);
    EXPECT_EQ(run("bake /nonexistent/tree.glb").first, 2);
    EXPECT_EQ(run("bake").first, 2);
}

}  // namespace
}  // namespace sylva
