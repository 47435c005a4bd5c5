// The LoDF rung's detail (systems/update_lodf_system.h): the leaves a plant keeps at a projected
// size, by hand.
#include "systems/update_lodf_system.h"

#include <gtest/gtest.h>

namespace sylva {
namespace {

// L·(size / top)² within [G, L]: 1000 leaves at half the take-over size keep a quarter, 250.
TEST(update_lodf, the_leaves_follow_the_projected_area_down_to_one_per_cluster) {
    EXPECT_EQ(lodf_leaves_at(1000, 10, 50.0f, 100.0f), 250u);
    EXPECT_EQ(lodf_leaves_at(1000, 10, 90.0f, 100.0f), 810u);
    EXPECT_EQ(lodf_leaves_at(1000, 10, 5.0f, 100.0f), 10u) << "0.25 % of 1000 is below G = 10";
    EXPECT_EQ(lodf_leaves_at(1000, 10, 120.0f, 100.0f), 1000u) << "above the rung's size: every leaf";
    EXPECT_EQ(lodf_leaves_at(1000, 10, 50.0f, 0.0f), 1000u) << "LoDF as the nearest rung is whole";
}

// The rung is whole above the upper edge of the band into it: 150 px x (1 + 0.1) = 165 px (a
// band after the reduced mesh; after the full mesh the step has none: 150 px).
TEST(update_lodf, the_rung_is_whole_above_its_band) {
    ladder l;
    l.rungs = {representation::mesh_reduced, representation::lodf, representation::billboard_cloud};
    l.below_px = {0.0f, 150.0f, 30.0f};
    l.band = {0.0f, 0.1f, 0.15f};
    l.count = 3;
    EXPECT_FLOAT_EQ(lodf_top_px(l), 165.0f);
    l.rungs[0] = representation::mesh_full;
    l.band[1] = 0.0f;
    EXPECT_FALSE(find_ladder_problem(l).has_value());
    EXPECT_FLOAT_EQ(lodf_top_px(l), 150.0f);
    l.rungs = {representation::lodf, representation::billboard_cloud};
    l.below_px = {0.0f, 30.0f};
    l.count = 2;
    EXPECT_EQ(lodf_top_px(l), 0.0f);
}

}  // namespace
}  // namespace sylva
