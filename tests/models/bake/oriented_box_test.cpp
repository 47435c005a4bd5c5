// PCA and minimum-volume boxes (Behrendt 2005 §2.2) on point sets whose minimum box is known by
// construction: rotated cuboids and cubes, a cuboid whose PCA frame is pulled askew, and the
// degenerate flat, collinear and single-point sets.
#include "models/bake/oriented_box.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>
#include <vector>

#include "models/random.h"

namespace sylva {
namespace {

constexpr float k_deg = 3.14159265f / 180.0f;

glm::mat3 rotation(float x_deg, float y_deg, float z_deg) {
    glm::mat4 r(1.0f);
    r = glm::rotate(r, z_deg * k_deg, glm::vec3(0, 0, 1));
    r = glm::rotate(r, y_deg * k_deg, glm::vec3(0, 1, 0));
    r = glm::rotate(r, x_deg * k_deg, glm::vec3(1, 0, 0));
    return glm::mat3(r);
}

// The 8 corners of an l.x x l.y x l.z cuboid centred at `center`, rotated by `r`, and `extra`
// random points inside it (they cannot change its minimum box).
std::vector<glm::vec3> cuboid(glm::vec3 l, const glm::mat3& r, glm::vec3 center, int extra, std::uint64_t seed) {
    std::vector<glm::vec3> points;
    for (int i = 0; i < 8; ++i)
        points.push_back(center + r * (glm::vec3(i & 1 ? 0.5f : -0.5f, i & 2 ? 0.5f : -0.5f, i & 4 ? 0.5f : -0.5f) * l));
    rng random(seed);
    for (int i = 0; i < extra; ++i)
        points.push_back(center + r * (glm::vec3(random.uniform(-0.5f, 0.5f), random.uniform(-0.5f, 0.5f),
                                                 random.uniform(-0.5f, 0.5f)) *
                                       l));
    return points;
}

// The volume a box around an l.x x l.y x l.z cuboid may have when its axes are off the
// cuboid's by at most `degrees` about every axis: each side grows by at most sin(angle) times
// the other two sides (|R_ij| <= sin(angle) off the diagonal, <= 1 on it).
float misaligned_volume(glm::vec3 l, float degrees) {
    const float s = std::sin(degrees * k_deg);
    return (l.x + s * (l.y + l.z)) * (l.y + s * (l.x + l.z)) * (l.z + s * (l.x + l.y));
}

void expect_finite(const oriented_box& box) {
    for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(std::isfinite(box.center[k]));
        EXPECT_TRUE(std::isfinite(box.half_extent[k]));
        EXPECT_GE(box.half_extent[k], 0.0f);
        for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(box.axes[std::size_t(k)][c]));
    }
}

void expect_right_handed_orthonormal(const oriented_box& box) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(glm::length(box.axes[std::size_t(k)]), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(box.axes[0], box.axes[1]), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(box.axes[0], box.axes[2]), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(box.axes[1], box.axes[2]), 0.0f, 1e-5f);
    EXPECT_GT(glm::dot(glm::cross(box.axes[0], box.axes[1]), box.axes[2]), 0.999f);
}

// Every point inside the box (up to rounding).
void expect_contains(const oriented_box& box, const std::vector<glm::vec3>& points) {
    for (const glm::vec3& p : points)
        for (int k = 0; k < 3; ++k)
            ASSERT_LE(std::abs(glm::dot(p - box.center, box.axes[std::size_t(k)])),
                      box.half_extent[k] + 1e-4f * (1.0f + glm::length(box.half_extent)));
}

oriented_box axis_aligned(const std::vector<glm::vec3>& points) {
    return fit_box(points, {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)});
}

TEST(oriented_box, fit_box_along_the_world_axes_is_the_bounding_box) {
    const std::vector<glm::vec3> points{{1, 2, 3}, {-1, 0, 5}, {0, 4, 4}};
    const oriented_box box = axis_aligned(points);
    EXPECT_EQ(box.center, glm::vec3(0, 2, 4));
    EXPECT_EQ(box.half_extent, glm::vec3(1, 2, 1));
    EXPECT_FLOAT_EQ(box.volume(), 16.0f);
}

TEST(oriented_box, pca_recovers_the_frame_of_a_cuboid_with_distinct_sides) {
    const glm::mat3 r = rotation(30, 20, 10);
    const std::vector<glm::vec3> points = cuboid({4, 2, 1}, r, {1, 2, 3}, 4000, 1);
    const oriented_box box = pca_box(points);
    expect_right_handed_orthonormal(box);
    expect_contains(box, points);
    // Largest variance first: the 4 m side, then 2 m, then 1 m.
    EXPECT_GT(std::abs(glm::dot(box.axes[0], r[0])), 0.995f);
    EXPECT_GT(std::abs(glm::dot(box.axes[1], r[1])), 0.995f);
    // Sampling noise tilts the frame a little: no worse than the 5.7° that 0.995 allows.
    EXPECT_GE(box.volume(), 8.0f * (1.0f - 1e-4f));
    EXPECT_LE(box.volume(), misaligned_volume({4, 2, 1}, 5.7f));
}

// From the world-aligned box (30°, 20°, 10° off) the search must find the cuboid: its volume
// (4 x 2 x 1 = 8) up to a one-degree misalignment (misaligned_volume: 9.33).
TEST(oriented_box, minimum_volume_box_recovers_a_rotated_cuboid_from_the_axis_aligned_box) {
    const glm::vec3 sides{4, 2, 1};
    for (const glm::vec3 angles : {glm::vec3(30, 20, 10), glm::vec3(-40, 5, 60), glm::vec3(0, 0, 33)}) {
        const std::vector<glm::vec3> points = cuboid(sides, rotation(angles.x, angles.y, angles.z), {5, 0, -2}, 200, 2);
        const oriented_box start = axis_aligned(points);
        const oriented_box box = minimum_volume_box(points, start);
        expect_right_handed_orthonormal(box);
        expect_contains(box, points);
        EXPECT_GE(box.volume(), 8.0f * (1.0f - 1e-4f));
        EXPECT_LE(box.volume(), misaligned_volume(sides, 1.0f)) << "angles " << angles.x << " " << angles.y << " "
                                                                  << angles.z << ", start " << start.volume();
        EXPECT_LT(box.volume(), start.volume());
    }
}

// A cube's covariance is isotropic, so PCA gives no useful frame; the search must still find
// the cube's orientation (volume 1, at most misaligned_volume = 1.107 for one degree).
TEST(oriented_box, minimum_volume_box_recovers_a_rotated_cube) {
    const glm::vec3 sides{1, 1, 1};
    const std::vector<glm::vec3> points = cuboid(sides, rotation(25, -35, 15), {0, 0, 0}, 300, 3);
    const oriented_box box = minimum_volume_box(points);
    expect_right_handed_orthonormal(box);
    expect_contains(box, points);
    EXPECT_GE(box.volume(), 1.0f - 1e-4f);
    EXPECT_LE(box.volume(), misaligned_volume(sides, 1.0f));
}

// The paper's observation in miniature: a dense blob in one corner of a 4 x 2 x 1 cuboid pulls
// the covariance, so the PCA box is tilted and larger; the rotation search gets back to 8.
TEST(oriented_box, minimum_volume_box_beats_a_skewed_pca_box) {
    const glm::mat3 r = rotation(10, 50, -20);
    std::vector<glm::vec3> points = cuboid({4, 2, 1}, r, {0, 0, 0}, 0, 4);
    rng random(5);
    for (int i = 0; i < 2000; ++i)
        points.push_back(r * glm::vec3(random.uniform(1.4f, 2.0f), random.uniform(0.6f, 1.0f), random.uniform(-0.5f, 0.5f)));
    const oriented_box pca = pca_box(points);
    const oriented_box box = minimum_volume_box(points, pca);
    EXPECT_GT(pca.volume(), 1.1f * box.volume()) << "the PCA box is not skewed: the test proves nothing";
    EXPECT_LE(box.volume(), misaligned_volume({4, 2, 1}, 1.0f));
    expect_contains(box, points);
}

TEST(oriented_box, minimum_volume_box_is_never_larger_than_its_initial_box) {
    rng random(6);
    for (int trial = 0; trial < 5; ++trial) {
        std::vector<glm::vec3> points;
        for (int i = 0; i < 100; ++i)
            points.push_back({random.uniform(-3, 3), random.uniform(0, 1), random.uniform(-1, 1) * float(trial)});
        const oriented_box pca = pca_box(points);
        EXPECT_LE(minimum_volume_box(points, pca).volume(), pca.volume() * (1.0f + 1e-5f)) << trial;
        const oriented_box aabb = axis_aligned(points);
        EXPECT_LE(minimum_volume_box(points, aabb).volume(), aabb.volume() * (1.0f + 1e-5f)) << trial;
    }
}

// A 3 x 2 rectangle in a tilted plane: zero volume, finite numbers, and among the zero-volume
// boxes the one with the smallest face (the rectangle itself, 6 m², up to one degree).
TEST(oriented_box, a_flat_set_gets_a_zero_thickness_box_with_the_smallest_face) {
    const glm::mat3 r = rotation(20, 30, 40);
    std::vector<glm::vec3> points;
    for (int i = 0; i <= 6; ++i)
        for (int j = 0; j <= 4; ++j) points.push_back(r * glm::vec3(-1.5f + 0.5f * float(i), -1.0f + 0.5f * float(j), 0.0f));
    for (const oriented_box& box : {pca_box(points), minimum_volume_box(points)}) {
        expect_finite(box);
        expect_right_handed_orthonormal(box);
        EXPECT_LT(box.volume(), 1e-4f);
        glm::vec3 sides = 2.0f * box.half_extent;
        std::sort(&sides[0], &sides[0] + 3);
        EXPECT_LT(sides[0], 1e-3f);
        EXPECT_LE(sides[1] * sides[2], (2.0f + 0.0175f * 3.0f) * (3.0f + 0.0175f * 2.0f));
        EXPECT_GE(sides[1] * sides[2], 6.0f - 1e-3f);
    }
}

TEST(oriented_box, collinear_and_single_point_sets_give_finite_boxes) {
    const glm::vec3 direction = glm::normalize(glm::vec3(1, 2, 3));
    std::vector<glm::vec3> line;
    for (int i = 0; i < 10; ++i) line.push_back(direction * float(i));
    for (const oriented_box& box : {pca_box(line), minimum_volume_box(line)}) {
        expect_finite(box);
        expect_right_handed_orthonormal(box);
        glm::vec3 sides = 2.0f * box.half_extent;
        std::sort(&sides[0], &sides[0] + 3);
        EXPECT_NEAR(sides[2], 9.0f, 1e-3f);
        EXPECT_LT(sides[1], 0.2f);  // at most one degree off the line: 9 sin 1° = 0.157
    }
    const std::vector<glm::vec3> one{{1, 2, 3}, {1, 2, 3}};
    for (const oriented_box& box : {pca_box(one), minimum_volume_box(one)}) {
        expect_finite(box);
        EXPECT_EQ(box.center, glm::vec3(1, 2, 3));
        EXPECT_EQ(box.volume(), 0.0f);
    }
}

TEST(oriented_box, bad_input_is_named) {
    EXPECT_THROW(pca_box({}), std::invalid_argument);
    const std::vector<glm::vec3> bad{{0, 0, 0}, {1, std::nanf(""), 0}};
    try {
        minimum_volume_box(bad);
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("point 1"), std::string::npos) << e.what();
    }
    const std::vector<glm::vec3> good{{0, 0, 0}, {1, 1, 1}};
    EXPECT_THROW(minimum_volume_box(good, axis_aligned(good), min_box_settings{0.0f, 4}), std::invalid_argument);
    oriented_box degenerate;
    degenerate.axes = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
    EXPECT_THROW(minimum_volume_box(good, degenerate), std::invalid_argument);
}

}  // namespace
}  // namespace sylva
