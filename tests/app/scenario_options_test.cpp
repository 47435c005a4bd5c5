// The command line's overrides of a scenario's lod section (app/scenario_options.h): a scenario
// whose ladder is chosen by a plant budget (the shipped `default`) still plays any other
// representation asked for, and a budget asked for with another representation is refused.
#include <gtest/gtest.h>

#include "app/scenario_options.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

TEST(scenario_options, another_representation_leaves_the_file_s_plant_budget) {
    scenario_options o;
    o.path = std::string(SYLVA_SOURCE_DIR) + "/scenarios/default.json";
    ASSERT_GT(load_with_overrides(o).lod.plant_budget_ms, 0.0);  // default plays the auto ladder
    o.representation = "points_lines";
    const scenario s = load_with_overrides(o);
    EXPECT_EQ(s.lod.representation, "points_lines");
    EXPECT_EQ(s.lod.plant_budget_ms, 0.0);
    o.plant_budget_ms = 10.0;  // asked for beside it: refused, naming the option
    try {
        (void)load_with_overrides(o);
        FAIL() << "a plant budget without a ladder was accepted";
    } catch (const scenario_error& e) {
        EXPECT_NE(std::string(e.what()).find("--plant-budget-ms"), std::string::npos) << e.what();
    }
}

TEST(scenario_options, a_zero_plant_budget_switches_the_ladder_by_projected_size) {
    scenario_options o;
    o.path = std::string(SYLVA_SOURCE_DIR) + "/scenarios/default.json";
    o.plant_budget_ms = 0.0;
    const scenario s = load_with_overrides(o);
    EXPECT_EQ(s.lod.representation, "ladder");
    EXPECT_EQ(s.lod.plant_budget_ms, 0.0);
}

TEST(scenario_options,
     a_frame_time_target_climbs_from_the_cheapest_rungs_not_from_the_file_s_budget) {
    scenario_options o;
    o.path = std::string(SYLVA_SOURCE_DIR) + "/scenarios/landscape.json";
    ASSERT_GT(load_with_overrides(o).lod.plant_budget_ms, 0.0);
    o.target_frame_ms = 150.0;
    scenario s = load_with_overrides(o);
    EXPECT_EQ(s.lod.target_frame_ms, 150.0);
    EXPECT_EQ(s.lod.plant_budget_ms, 0.0);
    o.plant_budget_ms = 40.0;  // a start given beside it is kept
    s = load_with_overrides(o);
    EXPECT_EQ(s.lod.target_frame_ms, 150.0);
    EXPECT_EQ(s.lod.plant_budget_ms, 40.0);
}

TEST(scenario_options, a_gain_alone_spends_what_each_frame_is_worth_not_the_file_s_budget) {
    scenario_options o;
    o.path = std::string(SYLVA_SOURCE_DIR) + "/scenarios/default.json";
    ASSERT_GT(load_with_overrides(o).lod.plant_budget_ms, 0.0);
    o.gain_per_ms = 40.0;
    scenario s = load_with_overrides(o);
    EXPECT_EQ(s.lod.gain_per_ms, 40.0);
    EXPECT_EQ(s.lod.plant_budget_ms, 0.0);
    o.plant_budget_ms = 60.0;  // a budget given beside it caps it
    s = load_with_overrides(o);
    EXPECT_EQ(s.lod.gain_per_ms, 40.0);
    EXPECT_EQ(s.lod.plant_budget_ms, 60.0);
    o.max_error = 0.05;  // an error threshold is another aim
    try {
        (void)load_with_overrides(o);
        FAIL() << "an error threshold beside a gain was accepted";
    } catch (const scenario_error& e) {
        EXPECT_NE(std::string(e.what()).find("--gain-per-ms"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace sylva
