// `sylva bake`: the first run bakes every species into the cache, the second finds them all.
#include <gtest/gtest.h>

#include "run_sylva.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <unistd.h>

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
    const auto first = run("bake " + scenario + " --cache " + cache.string());
    ASSERT_EQ(first.first, 0) << first.second;
    EXPECT_NE(first.second.find("2 species (model, crossed billboard, points and lines, billboard cloud each): 0 cache entries reused, 8 baked"), std::string::npos) << first.second;
    const auto second = run("bake " + scenario + " --cache " + cache.string());
    EXPECT_NE(second.second.find("2 species (model, crossed billboard, points and lines, billboard cloud each): 8 cache entries reused, 0 baked"), std::string::npos) << second.second;
    const auto forced = run("bake " + scenario + " --force --cache " + cache.string());
    EXPECT_NE(forced.second.find("0 cache entries reused, 8 baked"), std::string::npos) << forced.second;
    fs::remove_all(cache);
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
