// Behrendt 2005 §3.2 Eq. 1–2 (lod/shell_slanting.h) against hand values.
#include "lod/shell_slanting.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

namespace sylva {
namespace {

// x1 = (0,0,0), x2 = (3,0,0), x3 = (0,0,3): m = (1,0,1). Viewer (1,4,4): v = (0,4,3), |v| = 5.
// v·(m − x_i) = 3, 3, −6, so Eq. 2 gives 0.75, 0.75, −1.5 and the limited Eq. 2 (f = 1) 0.6,
// 0.6, −1.2; with f = 0.5, half of that.
TEST(shell_slanting, eq2_and_its_limit_by_hand) {
    const glm::vec3 x[3] = {{0, 0, 0}, {3, 0, 0}, {0, 0, 3}};
    const glm::vec3 m{1, 0, 1};
    const glm::vec3 c{1, 4, 4};
    const float exact[3] = {0.75f, 0.75f, -1.5f};
    const float limited[3] = {0.6f, 0.6f, -1.2f};
    for (int i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(slant_shift_exact(x[i], m, c), exact[i]);
        EXPECT_FLOAT_EQ(slant_shift(x[i], m, c, 1.0f), limited[i]);
        EXPECT_FLOAT_EQ(slant_shift(x[i], m, c, 0.5f), 0.5f * limited[i]);
        EXPECT_EQ(slant_shift(x[i], m, c, 0.0f), 0.0f);
    }
}

// Eq. 1 holds after Eq. 2's shift: v·(m − x'_i) = 0 for every vertex, and the shifts sum to 0,
// so the centre stays where it was.
TEST(shell_slanting, the_exact_shift_faces_the_triangle_to_the_viewer) {
    const glm::vec3 x[3] = {{2, 1, -1}, {4.5f, 1, 0.5f}, {1.5f, 1, 2}};
    const glm::vec3 m = (x[0] + x[1] + x[2]) / 3.0f;
    const glm::vec3 c{-20, 9, 35};
    float sum = 0.0f;
    for (const glm::vec3& xi : x) {
        const float d = slant_shift_exact(xi, m, c);
        EXPECT_NEAR(glm::dot(c - m, m - (xi + glm::vec3(0, d, 0))), 0.0f, 1e-4f);
        sum += d;
    }
    EXPECT_NEAR(sum, 0.0f, 1e-5f);
}

// As the view grazes the slice (v_y → 0), Eq. 2 grows without bound, the limited one stays within
// f·|m − x_i|: viewer (1, 0, 100) sees x1's offset (1,0,1) at cos 1/√2 along v = (0,0,99).
TEST(shell_slanting, the_limit_holds_as_the_view_grazes) {
    const glm::vec3 x1{0, 0, 0};
    const glm::vec3 m{1, 0, 1};
    EXPECT_TRUE(std::isinf(slant_shift_exact(x1, m, {1, 0, 100})));
    EXPECT_GT(slant_shift_exact(x1, m, {1, 0.01f, 100}), 1000.0f);
    EXPECT_FLOAT_EQ(slant_shift(x1, m, {1, 0, 100}, 1.0f), 1.0f);
    for (float height : {0.0f, 0.01f, 1.0f, 10.0f, 1000.0f})
        EXPECT_LE(std::abs(slant_shift(x1, m, {1, height, 100}, 1.0f)), std::sqrt(2.0f) + 1e-6f);
    EXPECT_EQ(slant_shift(x1, m, m, 1.0f), 0.0f) << "a viewer at the centre";
}

// On a coarser grid the shift is held to f times the ground's own reach: the same grazing view
// (1.0 unlimited) held to 0.5 at f = 1, to 0.25 at f = 0.5; within the reach nothing changes.
// A right triangle (0,0,0), (3,0,0), (0,0,3): centre (1,0,1), vertices √2, √5, √5 from it.
TEST(shell_slanting, coarse_triangles_shift_no_more_than_the_grounds_own) {
    const glm::vec3 x1{0, 0, 0};
    const glm::vec3 m{1, 0, 1};
    EXPECT_FLOAT_EQ(slant_shift(x1, m, {1, 0, 100}, 1.0f, 0.5f), 0.5f);
    EXPECT_FLOAT_EQ(slant_shift(x1, m, {1, 0, 100}, 0.5f, 0.5f), 0.25f);
    EXPECT_FLOAT_EQ(slant_shift(x1, m, {1, 0, 100}, 1.0f, 2.0f), 1.0f);
    EXPECT_FLOAT_EQ(slant_shift(m + (m - x1), m, {1, 0, 100}, 1.0f, 0.5f), -0.5f);
    mesh_data tile;
    tile.vertices.resize(3);
    tile.vertices[1].position = {3, 0, 0};
    tile.vertices[2].position = {0, 0, 3};
    tile.indices = {0, 1, 2};
    EXPECT_FLOAT_EQ(shell_slant_reach(std::span(&tile, 1)), std::sqrt(5.0f));
    EXPECT_EQ(shell_slant_reach({}), 0.0f);
}

}  // namespace
}  // namespace sylva
