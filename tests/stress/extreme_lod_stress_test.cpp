// Stress: LOD selection at extreme parameters. The rule (select_representation_system.cpp):
// full below reduced_distance x scale x lod_scale, reduced below far_distance x scale x
// lod_scale, else far. Comparisons with NaN are false, so a NaN distance (or a NaN factor)
// falls through to the far mesh and can never pick a finer one; a plant of scale 0 gets the far
// mesh at every distance.
#include <gtest/gtest.h>

#include <limits>

#include "app/stress/stress_checks.h"
#include "stress_support.h"
#include "systems/select_representation_system.h"

namespace sylva {
namespace {

TEST(extreme_lod_stress, lod_choice_and_loader_limits_are_sane) {
    const auto rows = check_extreme_lod(2);
    ASSERT_EQ(rows.size(), 4u);
    testing::expect_all_pass(rows);
    EXPECT_EQ(testing::row_named(rows, "LOD choice, ").value, 0.0);
}

TEST(extreme_lod_stress, hand_checked_switch_distances_at_lod_scale_0_01_and_100) {
    species_entry s;
    s.reduced_distance_m = 30.0f;
    s.far_distance_m = 60.0f;
    // lod_scale 0.01: switches at 0.3 m and 0.6 m.
    EXPECT_EQ(choose_representation(s, 0.29f, 1.0f, 0.01f), representation::mesh_full);
    EXPECT_EQ(choose_representation(s, 0.31f, 1.0f, 0.01f), representation::mesh_reduced);
    EXPECT_EQ(choose_representation(s, 0.61f, 1.0f, 0.01f), representation::mesh_far);
    // lod_scale 100: switches at 3000 m and 6000 m.
    EXPECT_EQ(choose_representation(s, 2999.0f, 1.0f, 100.0f), representation::mesh_full);
    EXPECT_EQ(choose_representation(s, 3001.0f, 1.0f, 100.0f), representation::mesh_reduced);
    EXPECT_EQ(choose_representation(s, 6001.0f, 1.0f, 100.0f), representation::mesh_far);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(choose_representation(s, 0.0f, 1.0f, 1.0f), representation::mesh_full);
    EXPECT_EQ(choose_representation(s, 1e-30f, 1.0f, 1.0f), representation::mesh_full);
    EXPECT_EQ(choose_representation(s, 1e30f, 1.0f, 100.0f), representation::mesh_far);
    EXPECT_EQ(choose_representation(s, inf, 1.0f, 100.0f), representation::mesh_far);
    EXPECT_EQ(choose_representation(s, nan, 1.0f, 100.0f), representation::mesh_far);
    EXPECT_EQ(choose_representation(s, 0.0f, 0.0f, 1.0f), representation::mesh_far);  // scale 0
    EXPECT_EQ(choose_representation(s, 1.0f, nan, 1.0f), representation::mesh_far);
}

}  // namespace
}  // namespace sylva
