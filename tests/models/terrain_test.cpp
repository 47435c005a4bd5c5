#include "models/terrain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

namespace sylva {
namespace {

// A 3 x 3 field, 2 m across (1 m spacing), heights set by hand.
heightfield hand_field(float (*h)(double x, double z)) {
    heightfield f;
    f.resolution = 3;
    f.size_m = 2.0;
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column) f.heights.push_back(h(column - 1.0, row - 1.0));
    return f;
}

TEST(terrain, height_at_grid_vertices_equals_stored_heights) {
    const heightfield f = generate_terrain(100.0, 17, 20.0f, 4, 0.02f, 3);
    for (std::uint32_t row = 0; row < f.resolution; ++row)
        for (std::uint32_t column = 0; column < f.resolution; ++column)
            ASSERT_NEAR(f.height_at(column * f.spacing() - 50.0, row * f.spacing() - 50.0), f.at(column, row), 1e-4f);
}

TEST(terrain, height_at_is_bilinear_between_vertices) {
    heightfield f = hand_field([](double, double) { return 0.0f; });
    f.heights = {0, 0, 0, 0, 1, 2, 0, 3, 8};  // rows z = -1, 0, 1
    EXPECT_FLOAT_EQ(f.height_at(0.5, 0.5), (1.0f + 2.0f + 3.0f + 8.0f) / 4.0f);  // cell centre
    EXPECT_FLOAT_EQ(f.height_at(0.5, 0.0), 1.5f);                                // edge midpoint
    EXPECT_FLOAT_EQ(f.height_at(0.25, 1.0), 3.0f + 0.25f * 5.0f);
    EXPECT_FLOAT_EQ(f.height_at(5.0, 5.0), 8.0f);    // clamped outside
    EXPECT_FLOAT_EQ(f.height_at(-5.0, -5.0), 0.0f);
}

TEST(terrain, flat_field_normals_point_up_and_slope_is_zero) {
    const heightfield f = hand_field([](double, double) { return 4.0f; });
    const glm::vec3 n = f.normal_at(0.3, -0.2);
    EXPECT_FLOAT_EQ(n.x, 0.0f);
    EXPECT_FLOAT_EQ(n.y, 1.0f);
    EXPECT_FLOAT_EQ(n.z, 0.0f);
    EXPECT_FLOAT_EQ(f.slope_deg_at(0.0, 0.0), 0.0f);
    for (const vertex& v : terrain_mesh(f, 4.0f).vertices) EXPECT_FLOAT_EQ(v.normal.y, 1.0f);
}

TEST(terrain, slope_of_a_plane_matches_hand_value) {
    // h = 0.5 x + 0.5 z: gradient length sqrt(0.5) -> atan(0.7071) = 35.264 degrees.
    const heightfield f = hand_field([](double x, double z) { return float(0.5 * x + 0.5 * z); });
    EXPECT_NEAR(f.slope_deg_at(0.1, -0.3), 35.2644f, 1e-3f);
    const glm::vec3 n = f.normal_at(0.1, -0.3);
    EXPECT_NEAR(n.x, -0.5f / std::sqrt(1.5f), 1e-5f);
    EXPECT_NEAR(n.y, 1.0f / std::sqrt(1.5f), 1e-5f);
    // A 45-degree ramp along x.
    const heightfield ramp = hand_field([](double x, double) { return float(x); });
    EXPECT_NEAR(ramp.slope_deg_at(0.0, 0.0), 45.0f, 1e-4f);
}

TEST(terrain, generation_is_deterministic_and_seeded) {
    const heightfield a = generate_terrain(400.0, 65, 25.0f, 5, 0.008f, 7);
    const heightfield b = generate_terrain(400.0, 65, 25.0f, 5, 0.008f, 7);
    const heightfield c = generate_terrain(400.0, 65, 25.0f, 5, 0.008f, 8);
    EXPECT_EQ(a.heights, b.heights);
    EXPECT_NE(a.heights, c.heights);
    EXPECT_LE(a.max_height, 12.5f);
    EXPECT_GE(a.min_height, -12.5f);
    EXPECT_GT(a.max_height - a.min_height, 3.0f);  // there are hills
}

TEST(terrain, same_landscape_at_another_resolution) {
    const heightfield coarse = generate_terrain(400.0, 33, 25.0f, 3, 0.008f, 7);
    const heightfield fine = generate_terrain(400.0, 65, 25.0f, 3, 0.008f, 7);
    EXPECT_FLOAT_EQ(coarse.at(16, 16), fine.at(32, 32));
}

TEST(terrain, mesh_layout_uv_and_bounds) {
    const heightfield f = generate_terrain(64.0, 9, 10.0f, 3, 0.05f, 1);
    const mesh_data m = terrain_mesh(f, 4.0f);
    ASSERT_EQ(m.vertices.size(), 81u);
    EXPECT_EQ(m.triangle_count(), 8u * 8u * 2u);
    ASSERT_EQ(m.submeshes.size(), 1u);
    EXPECT_EQ(m.submeshes[0].material, material_kind::ground);
    EXPECT_EQ(m.submeshes[0].index_count, m.indices.size());
    EXPECT_FLOAT_EQ(m.vertices[0].position.x, -32.0f);
    EXPECT_FLOAT_EQ(m.vertices[80].position.z, 32.0f);
    EXPECT_FLOAT_EQ(m.vertices[80].uv.x, 8.0f);  // 32 m / 4 m per repeat
    EXPECT_FLOAT_EQ(m.bounds_min.y, f.min_height);
    EXPECT_FLOAT_EQ(m.bounds_max.y, f.max_height);
    // Front faces point up: the first triangle's geometric normal has positive y.
    const glm::vec3 a = m.vertices[m.indices[0]].position;
    const glm::vec3 b = m.vertices[m.indices[1]].position;
    const glm::vec3 c = m.vertices[m.indices[2]].position;
    EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
}

TEST(terrain, rejects_bad_arguments) {
    EXPECT_THROW(generate_terrain(100.0, 1, 1.0f, 1, 0.1f, 0), std::invalid_argument);
    EXPECT_THROW(generate_terrain(0.0, 9, 1.0f, 1, 0.1f, 0), std::invalid_argument);
}

}  // namespace
}  // namespace sylva
