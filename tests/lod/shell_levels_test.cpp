// Behrendt 2005 §3.3's level of detail on shells (lod/shell_levels.h), by hand.
#include "lod/shell_levels.h"

#include "components/shell_tile.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sylva {
namespace {

// h = 0.5 m, 500 px per radian, p_min = 2 px: λ = log2(d · 2 / 250) = log2(d / 125).
// d = 250 m: λ = 1 exactly, level 1, no merge; d = 400: λ = 1.678, into the last 0.5 of level 1
// by 0.178 / 0.5 = 0.356; d = 100: λ < 0, level 0; d = 2000: λ = 4 ≥ max_level 3: level 3.
TEST(shell_levels, the_level_follows_the_slice_spacing_on_screen) {
    const auto at = [](float d) { return shell_level_at(d, 0.5f, 500.0f, 2.0f, 3, 0.5f); };
    EXPECT_EQ(at(250.0f).level, 1u);
    EXPECT_FLOAT_EQ(at(250.0f).merge, 0.0f);
    EXPECT_EQ(at(400.0f).level, 1u);
    EXPECT_NEAR(at(400.0f).merge, (std::log2(400.0f / 125.0f) - 1.5f) / 0.5f, 1e-5f);
    EXPECT_NEAR(at(400.0f).merge, 0.356f, 1e-3f);
    EXPECT_EQ(at(100.0f).level, 0u);
    EXPECT_EQ(at(300.0f).merge, 0.0f) << "λ = 1.263: before the band";
    EXPECT_EQ(at(2000.0f).level, 3u);
    EXPECT_EQ(at(2000.0f).merge, 0.0f);
    // Just below λ = 2 the pairs of level 1 have all but met; at λ = 2, level 2 takes over.
    EXPECT_EQ(at(499.0f).level, 1u);
    EXPECT_GT(at(499.0f).merge, 0.99f);
    EXPECT_EQ(at(500.0f).level, 2u);
}

// A vertical offset shows as Δy·sin θ / d: a level is chosen at d / sin θ. Looking 30 across
// and 40 down (d = 50, sin θ = 30 / 50): 50 / 0.6 = 83.33 m; level (no height to hide): 50 m;
// straight down, sin θ is held at 1/1000: 10 m → 10 km.
TEST(shell_levels, slices_seen_from_above_merge_sooner) {
    EXPECT_NEAR(shell_level_distance({30.0f, -40.0f, 0.0f}), 83.333f, 1e-3f);
    EXPECT_NEAR(shell_level_distance({40.0f, 0.0f, 30.0f}), 50.0f, 1e-4f);
    EXPECT_NEAR(shell_level_distance({0.0f, -10.0f, 0.0f}), 10000.0f, 1e-1f);
    EXPECT_EQ(shell_level_distance({0.0f, 0.0f, 0.0f}), 0.0f);
}

// h = 1: level 1's slices are 2 m slabs drawn at 1, 3, 5 m; at merge 0.5 slices 0 and 1 move
// half way to their common centre 2 (1.5 and 2.5), and at merge 1 both are at 2, the centre of
// level 2's slice 0 ((0 + ½)·4 = 2): the replacement is drawn where the pair met. An unpaired
// top slice (3 slices) stays.
TEST(shell_levels, pairs_move_together_until_they_touch_where_their_merge_is_drawn) {
    EXPECT_FLOAT_EQ(shell_slice_height(0, 1, 0.0f, 1.0f, 4), 1.0f);
    EXPECT_FLOAT_EQ(shell_slice_height(1, 1, 0.0f, 1.0f, 4), 3.0f);
    EXPECT_FLOAT_EQ(shell_slice_height(0, 1, 0.5f, 1.0f, 4), 1.5f);
    EXPECT_FLOAT_EQ(shell_slice_height(1, 1, 0.5f, 1.0f, 4), 2.5f);
    EXPECT_FLOAT_EQ(shell_slice_height(0, 1, 1.0f, 1.0f, 4), 2.0f);
    EXPECT_FLOAT_EQ(shell_slice_height(1, 1, 1.0f, 1.0f, 4), 2.0f);
    EXPECT_FLOAT_EQ(shell_slice_height(0, 2, 0.0f, 1.0f, 2), 2.0f);
    EXPECT_FLOAT_EQ(shell_slice_height(3, 1, 1.0f, 1.0f, 4), 6.0f);  // pair (2, 3) meets at 6
    EXPECT_FLOAT_EQ(shell_slice_height(2, 1, 1.0f, 1.0f, 3), 5.0f) << "unpaired";
}

// 16 slices: 16, 8, 4, 2, 1 (five levels); 5 slices: 5, 3, 2, 1 (an odd top slice carried up).
TEST(shell_levels, a_pyramid_halves_its_slices_level_by_level) {
    EXPECT_EQ(shell_pyramid_levels(16), 5u);
    EXPECT_EQ(shell_slices_at_level(16, 2), 4u);
    EXPECT_EQ(shell_pyramid_levels(5), 4u);
    EXPECT_EQ(shell_slices_at_level(5, 1), 3u);
    EXPECT_EQ(shell_slices_at_level(5, 3), 1u);
    EXPECT_EQ(shell_pyramid_levels(1), 1u);
}

}  // namespace
}  // namespace sylva
