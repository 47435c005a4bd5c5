// How a shell fragment reads its slice at a grazing view (lod/shell_sampling.h): opacity along the
// view (Engel et al. 2006 §9.1) and the footprint cut into fetches.
#include "lod/shell_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace sylva {
namespace {

// By hand: half the light through one slab, twice its thickness crossed: 1 − 0.5² = 0.75; three
// times 0.2: 1 − 0.8³ = 0.488.
TEST(shell_sampling, opacity_over_a_longer_path_is_that_of_the_slab_crossed_that_many_times) {
    EXPECT_FLOAT_EQ(opacity_along(0.5f, 2.0f), 0.75f);
    EXPECT_NEAR(opacity_along(0.2f, 3.0f), 0.488f, 1e-6f);
    EXPECT_FLOAT_EQ(opacity_along(0.3f, 1.0f), 0.3f);
    EXPECT_FLOAT_EQ(opacity_along(0.0f, 11.5f), 0.0f);
    // An opaque texel is held at 0.999, so the power stays finite: over half its thickness it
    // shows 1 − 0.001^0.5.
    EXPECT_NEAR(opacity_along(1.0f, 0.5f), 1.0f - std::sqrt(0.001f), 1e-6f);
}

// A flat slice seen from 30° above: p = 1 / sin 30° = 2; from 5°: 11.47; from straight above: 1.
// Slanted 45° toward a viewer 30° up on the -x side: n = (-0.7071, 0.7071, 0), v = (0.8660,
// -0.5, 0), |v · n| = 0.6124 + 0.3536 = 0.9659, p = 0.7071 / 0.9659 = 0.7321: the slice faces the
// view and the tilted slab is crossed more nearly straight than from above.
TEST(shell_sampling, the_path_through_a_slab_grows_as_the_view_grazes_it) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const auto at = [](float deg) {
        const float e = glm::radians(deg);
        return glm::vec3(std::cos(e), -std::sin(e), 0.0f);
    };
    EXPECT_NEAR(slab_path(at(30.0f), up), 2.0f, 1e-5f);
    EXPECT_NEAR(slab_path(at(5.0f), up), 11.474f, 1e-3f);
    EXPECT_NEAR(slab_path(glm::vec3(0.0f, -3.0f, 0.0f), up), 1.0f, 1e-6f);
    EXPECT_NEAR(slab_path(at(30.0f), -up), 2.0f, 1e-5f) << "either side of the slice";
    const glm::vec3 slanted = glm::normalize(glm::vec3(-1.0f, 1.0f, 0.0f));
    EXPECT_NEAR(slab_path(at(30.0f), slanted), 0.7321f, 1e-4f);
    // Edge-on: held.
    EXPECT_EQ(slab_path(at(0.0f), up), k_shell_max_path);
    EXPECT_EQ(slab_path(at(1.0f), up), k_shell_max_path);
}

// By hand: from 30° above, sin 30° = 1/2, so a from-above mean (0.1, 0.8, -0.2) lights as
// (0.05, 0.4, -0.1); straight down it is kept; from the horizon it is an even spread (0); the
// view's length and direction along it do not matter.
TEST(shell_sampling, the_slices_normal_shortens_as_the_view_grazes_them) {
    const glm::vec3 n(0.1f, 0.8f, -0.2f);
    const glm::vec3 from_30(std::cos(glm::radians(30.0f)), -0.5f, 0.0f);
    const glm::vec3 half = seen_normal(n, from_30);
    EXPECT_NEAR(half.x, 0.05f, 1e-6f);
    EXPECT_NEAR(half.y, 0.4f, 1e-6f);
    EXPECT_NEAR(half.z, -0.1f, 1e-6f);
    EXPECT_NEAR(glm::length(seen_normal(n, 7.0f * from_30) - half), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(seen_normal(n, -from_30) - half), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(seen_normal(n, glm::vec3(0.0f, -2.0f, 0.0f)) - n), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(seen_normal(n, glm::vec3(0.0f, 0.0f, -5.0f))), 0.0f, 1e-6f);
}

// A footprint 11 texels long and 1 wide takes the most fetches; a round one, one; 2.5 : 1, three.
TEST(shell_sampling, a_long_footprint_is_cut_into_fetches) {
    EXPECT_EQ(footprint_taps({1.0f, 0.0f}, {0.0f, 11.0f}), k_shell_max_taps);
    EXPECT_EQ(footprint_taps({0.0f, 11.0f}, {1.0f, 0.0f}, 16), 11);
    EXPECT_EQ(footprint_taps({0.5f, 0.0f}, {0.0f, 0.5f}), 1);
    EXPECT_EQ(footprint_taps({0.0f, 0.0f}, {0.0f, 0.0f}), 1);
    EXPECT_EQ(footprint_taps({3.0f, 4.0f}, {0.0f, 2.0f}), 3);
}

}  // namespace
}  // namespace sylva
