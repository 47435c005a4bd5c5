// Every scenario shipped in scenarios/ loads, and the library meets the sizes issue 3 names.
#include <gtest/gtest.h>

#include <filesystem>

#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

std::uint64_t plants_requested(const scenario& s, std::string_view species_filter = {}) {
    std::uint64_t n = 0;
    for (const auto& p : s.populations)
        if (species_filter.empty() || species_filter.find(p.species) != std::string_view::npos) n += p.count;
    return n;
}

scenario library(const char* name) {
    return load_scenario_file(fs::path(SYLVA_SOURCE_DIR) / "scenarios" / (std::string(name) + ".json"));
}

TEST(scenario_library, every_shipped_scenario_loads) {
    std::size_t count = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(SYLVA_SOURCE_DIR) / "scenarios")) {
        if (entry.path().extension() != ".json") continue;
        EXPECT_NO_THROW(load_scenario_file(entry.path())) << entry.path();
        ++count;
    }
    EXPECT_GE(count, 6u);  // default, tiny, single_tree, forest, meadow, landscape
}

TEST(scenario_library, sizes_match_what_each_scenario_promises) {
    EXPECT_EQ(plants_requested(library("single_tree")), 1u);
    EXPECT_GE(plants_requested(library("forest"), "oak spruce"), 10000u);
    EXPECT_GE(plants_requested(library("meadow")), 100000u);
    EXPECT_GE(plants_requested(library("landscape")), 50000u);
    // Issue 24: at least 20,000 trees and a dense understorey, Wang-tiled for the shells.
    EXPECT_GE(plants_requested(library("valley"), "oak spruce"), 20000u);
    EXPECT_GE(plants_requested(library("valley"), "hazel"), 20000u);
}

// Issue 21 item 5: every scenario a user plays draws the auto ladder under a plant budget, the
// test suite's `tiny` too (its tests ask for mesh levels themselves: tests/tiny_scene.h).
TEST(scenario_library, every_scenario_plays_the_auto_ladder) {
    std::size_t count = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(SYLVA_SOURCE_DIR) / "scenarios")) {
        if (entry.path().extension() != ".json") continue;
        const scenario s = load_scenario_file(entry.path());
        EXPECT_EQ(s.lod.representation, "ladder") << entry.path();
        EXPECT_GT(s.lod.plant_budget_ms, 0.0) << entry.path();
        ++count;
    }
    EXPECT_GE(count, 8u);  // with tiny, time_of_day and valley
}

}  // namespace
}  // namespace sylva
