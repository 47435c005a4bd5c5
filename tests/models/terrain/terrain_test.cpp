#include "models/terrain/terrain.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <map>
#include <string>
#include <tuple>
#include <vector>

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

// --- heightmaps ------------------------------------------------------------------------------

std::filesystem::path temp_file(const std::string& name) {
    return std::filesystem::temp_directory_path() / ("sylva_terrain_test_" + name);
}

template <class T>
void write_image(const std::filesystem::path& path, int width, int height, int channels,
                 OIIO::TypeDesc type, const std::vector<T>& pixels) {
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out) << OIIO::geterror();
    ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(width, height, channels, type)))
        << out->geterror();
    ASSERT_TRUE(out->write_image(type, pixels.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

TEST(heightmap, sixteen_bit_png_maps_full_range_to_height) {
    const auto path = temp_file("h16.png");
    // 4 x 4: a ramp along x, 0 .. 65535.
    std::vector<std::uint16_t> pixels;
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) pixels.push_back(std::uint16_t(column * 21845));
    write_image(path, 4, 4, 1, OIIO::TypeDesc::UINT16, pixels);
    const heightfield f = load_heightmap(path, 30.0, 90.0f);
    EXPECT_EQ(f.resolution, 4u);
    EXPECT_EQ(f.size_m, 30.0);
    EXPECT_NEAR(f.at(0, 2), 0.0f, 1e-5f);
    EXPECT_NEAR(f.at(1, 0), 30.0f, 1e-3f);
    EXPECT_NEAR(f.at(3, 3), 90.0f, 1e-3f);
    EXPECT_NEAR(f.min_height, 0.0f, 1e-5f);
    EXPECT_NEAR(f.max_height, 90.0f, 1e-3f);
    EXPECT_NEAR(f.height_at(-15.0, 0.0), 0.0f, 1e-3f);  // column 0 is x = -size/2
    std::filesystem::remove(path);
}

TEST(heightmap, float_exr_uses_the_first_channel_and_row_zero_is_minus_z) {
    const auto path = temp_file("rgb.exr");
    std::vector<float> pixels;  // 3 x 3 RGB; R = 0.1 * (row * 3 + column), G and B noise
    for (int i = 0; i < 9; ++i) pixels.insert(pixels.end(), {0.1f * float(i), 7.0f, -3.0f});
    write_image(path, 3, 3, 3, OIIO::TypeDesc::FLOAT, pixels);
    const heightfield f = load_heightmap(path, 2.0, 10.0f);
    EXPECT_EQ(f.resolution, 3u);
    EXPECT_NEAR(f.at(2, 0), 2.0f, 1e-5f);
    EXPECT_NEAR(f.at(0, 2), 6.0f, 1e-5f);
    EXPECT_NEAR(f.height_at(1.0, -1.0), 2.0f, 1e-5f);  // row 0 at z = -1
    std::filesystem::remove(path);
}

TEST(heightmap, missing_non_square_and_unreadable_files_are_named) {
    const auto missing = temp_file("missing.png");
    try {
        load_heightmap(missing, 10.0, 1.0f);
        ADD_FAILURE();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
    }
    const auto wide = temp_file("wide.png");
    write_image(wide, 3, 2, 1, OIIO::TypeDesc::UINT16, std::vector<std::uint16_t>(6, 0));
    try {
        load_heightmap(wide, 10.0, 1.0f);
        ADD_FAILURE();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(wide.string() + " is 3x2 pixels"), std::string::npos)
            << e.what();
    }
    const auto garbage = temp_file("garbage.png");
    std::FILE* file = std::fopen(garbage.string().c_str(), "wb");
    std::fputs("not a png", file);
    std::fclose(file);
    try {
        load_heightmap(garbage, 10.0, 1.0f);
        ADD_FAILURE();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(garbage.string()), std::string::npos) << e.what();
    }
    std::filesystem::remove(wide);
    std::filesystem::remove(garbage);
}

// --- terrain in tiles ----------------------------------------------------------------------

TEST(terrain_tiles, tiles_have_the_full_meshs_triangles_and_vertices) {
    const heightfield f =
        generate_terrain(100.0, 34, 20.0f, 4, 0.02f, 3);  // 33 cells: uneven split
    const mesh_data full = terrain_mesh(f, 4.0f);
    for (std::uint32_t tiles : {1u, 2u, 4u, 8u, 33u, 1000u}) {
        SCOPED_TRACE(tiles);
        const auto meshes = terrain_tile_meshes(f, tiles, 4.0f);
        EXPECT_EQ(meshes.size(), std::size_t(std::min(tiles, 33u)) * std::min(tiles, 33u));
        std::size_t triangles = 0;
        // Every tile vertex is a vertex of the full mesh, bit for bit.
        std::map<std::tuple<float, float>, const vertex*> by_xz;
        for (const vertex& v : full.vertices) by_xz[{v.position.x, v.position.z}] = &v;
        for (const mesh_data& m : meshes) {
            triangles += m.triangle_count();
            ASSERT_EQ(m.submeshes.size(), 1u);
            EXPECT_EQ(m.submeshes[0].material, material_kind::ground);
            for (const vertex& v : m.vertices) {
                const vertex* same = by_xz.at({v.position.x, v.position.z});
                ASSERT_EQ(v.position, same->position);
                ASSERT_EQ(v.normal, same->normal);
                ASSERT_EQ(v.uv, same->uv);
                EXPECT_GE(v.position.y, m.bounds_min.y);
                EXPECT_LE(v.position.y, m.bounds_max.y);
            }
        }
        EXPECT_EQ(triangles, full.triangle_count());
    }
}

TEST(terrain_tiles, neighbours_share_their_edge_exactly) {
    const heightfield f = generate_terrain(64.0, 33, 15.0f, 4, 0.03f, 9);
    const auto meshes = terrain_tile_meshes(f, 4, 1.0f);  // 8 cells, 9 vertices per tile side
    constexpr std::uint32_t n = 9;
    const auto at = [&](std::uint32_t tile, std::uint32_t column,
                        std::uint32_t row) -> const vertex& {
        return meshes[tile].vertices[row * n + column];
    };
    for (std::uint32_t row = 0; row < n; ++row) {  // tile 0's right edge is tile 1's left edge
        EXPECT_EQ(at(0, n - 1, row).position, at(1, 0, row).position);
        EXPECT_EQ(at(0, n - 1, row).normal, at(1, 0, row).normal);
    }
    for (std::uint32_t column = 0; column < n;
         ++column) {  // tile 0's far edge is tile 4's near edge
        EXPECT_EQ(at(0, column, n - 1).position, at(4, column, 0).position);
        EXPECT_EQ(at(0, column, n - 1).normal, at(4, column, 0).normal);
    }
    // Bounds are the tile's own: x range of tile 1 is one quarter of the terrain.
    EXPECT_FLOAT_EQ(meshes[1].bounds_min.x, -16.0f);
    EXPECT_FLOAT_EQ(meshes[1].bounds_max.x, 0.0f);
}

// Coarser grids for far surfaces (the shells' slices): a 5 x 5 field, 4 cells, flat but for a
// 3 m peak at its centre sample. Stride 2 keeps the centre (samples 0, 2, 4): the coarse
// triangles then reach 1.5 m half way to it, where the field is 0 (e.g. column 2, row 1:
// u = 1, v = 1/2 on the upper triangle, 3 + (1 - 1/2)(0 - 3) = 1.5). Stride 4 keeps the corners
// only: flat, 3 m under the peak. Stride 3: samples 0, 3 and the last, 4.
TEST(terrain_tiles, coarser_grids_keep_every_stride_th_sample_and_say_how_far_they_stray) {
    heightfield f;
    f.resolution = 5;
    f.size_m = 4.0;
    f.heights.assign(25, 0.0f);
    f.heights[2 * 5 + 2] = 3.0f;
    f.max_height = 3.0f;
    EXPECT_EQ(terrain_tile_meshes(f, 1, 1.0f, 1)[0].vertices.size(), 25u);
    EXPECT_EQ(terrain_tile_meshes(f, 1, 1.0f, 2)[0].vertices.size(), 9u);
    EXPECT_EQ(terrain_tile_meshes(f, 1, 1.0f, 2)[0].triangle_count(), 8u);
    EXPECT_EQ(terrain_tile_meshes(f, 1, 1.0f, 4)[0].triangle_count(), 2u);
    const mesh_data three = terrain_tile_meshes(f, 1, 1.0f, 3)[0];
    ASSERT_EQ(three.vertices.size(), 9u);
    EXPECT_FLOAT_EQ(three.vertices[1].position.x, 1.0f);  // column 3 of 0..4, x from -2
    EXPECT_FLOAT_EQ(three.vertices[2].position.x, 2.0f);
    EXPECT_FLOAT_EQ(terrain_tile_errors(f, 1, 1)[0], 0.0f);
    EXPECT_FLOAT_EQ(terrain_tile_errors(f, 1, 2)[0], 1.5f);
    EXPECT_FLOAT_EQ(terrain_tile_errors(f, 1, 4)[0], 3.0f);
    // Two tiles per side, stride 2: each tile is one coarse cell whose far corner is the peak.
    const std::vector<float> quarters = terrain_tile_errors(f, 2, 2);
    ASSERT_EQ(quarters.size(), 4u);
    for (float e : quarters) EXPECT_FLOAT_EQ(e, 1.5f);
    EXPECT_THROW(terrain_tile_meshes(f, 1, 1.0f, 0), std::invalid_argument);
    EXPECT_THROW(terrain_tile_errors(f, 1, 0), std::invalid_argument);
}

// Skirts (terrain_tile_skirts): a 5 x 5 field in 2 x 2 tiles of 2 cells. Tile 0 (the -x, -z
// corner) has two sides inside the terrain, east and south: 2 sides x 3 samples x 2 vertices, 2
// sides x 2 segments x 2 triangles. Its top vertices are the grid's own, bit for bit; its bottom
// ones hang the tile's depth below them; every triangle faces out of the tile (GL's
// counter-clockwise front faces, the ground's back faces culled). Tile 3 has west and north.
TEST(terrain_tiles, skirts_hang_from_the_inner_edges_and_face_out_of_their_tile) {
    const heightfield f = generate_terrain(4.0, 5, 3.0f, 3, 0.3f, 5);
    const std::vector<float> depth{2.0f, 1.0f, 1.0f, 0.5f};
    const std::vector<mesh_data> skirts = terrain_tile_skirts(f, 2, 1.0f, 1, depth);
    const std::vector<mesh_data> tiles = terrain_tile_meshes(f, 2, 1.0f, 1);
    ASSERT_EQ(skirts.size(), 4u);
    for (std::size_t t = 0; t < 4; ++t) {
        SCOPED_TRACE(t);
        const mesh_data& skirt = skirts[t];
        ASSERT_EQ(skirt.vertices.size(), 12u);
        ASSERT_EQ(skirt.triangle_count(), 8u);
        ASSERT_EQ(skirt.submeshes.size(), 1u);
        EXPECT_EQ(skirt.submeshes[0].material, material_kind::ground);
        const glm::vec3 centre = 0.5f * (tiles[t].bounds_min + tiles[t].bounds_max);
        for (std::size_t i = 0; i < skirt.vertices.size(); i += 2) {
            const vertex& top = skirt.vertices[i];
            const vertex& bottom = skirt.vertices[i + 1];
            const auto same = std::find_if(
                tiles[t].vertices.begin(), tiles[t].vertices.end(), [&](const vertex& v) {
                    return v.position == top.position && v.normal == top.normal && v.uv == top.uv;
                });
            EXPECT_NE(same, tiles[t].vertices.end());
            EXPECT_NEAR(top.position.y - bottom.position.y, depth[t], 1e-5f);
            EXPECT_EQ(glm::vec2(top.position.x, top.position.z),
                      glm::vec2(bottom.position.x, bottom.position.z));
            EXPECT_EQ(top.normal, bottom.normal);
            // On an inner edge of the tile (x or z = 0), never on the terrain's border (+-2).
            EXPECT_TRUE(top.position.x == 0.0f || top.position.z == 0.0f);
        }
        for (std::size_t k = 0; k < skirt.indices.size(); k += 3) {
            const glm::vec3 a = skirt.vertices[skirt.indices[k]].position;
            const glm::vec3 b = skirt.vertices[skirt.indices[k + 1]].position;
            const glm::vec3 c = skirt.vertices[skirt.indices[k + 2]].position;
            const glm::vec3 facing = glm::cross(b - a, c - a);
            const glm::vec3 outward = (a + b + c) / 3.0f - centre;
            EXPECT_GT(facing.x * outward.x + facing.z * outward.z, 0.0f);
            EXPECT_FLOAT_EQ(facing.y, 0.0f);
        }
    }
    // No depth, or one tile: no side can part, no skirt.
    EXPECT_TRUE(terrain_tile_skirts(f, 2, 1.0f, 1, std::vector<float>(4, 0.0f))[0].indices.empty());
    EXPECT_TRUE(terrain_tile_skirts(f, 1, 1.0f, 1, std::vector<float>{1.0f})[0].indices.empty());
    EXPECT_THROW(terrain_tile_skirts(f, 2, 1.0f, 1, std::vector<float>{1.0f}),
                 std::invalid_argument);
    EXPECT_THROW(terrain_tile_skirts(f, 2, 1.0f, 0, depth), std::invalid_argument);
}

}  // namespace
}  // namespace sylva
