#include "models/bake/crossed_billboard.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "models/bake/transfer_pages.h"
#include "models/cache/bake_cache.h"
#include "models/cache/billboard_io.h"
#include "models/generate/plant_library.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_resolution = 128;

const plant_model& broadleaf() {
    static const plant_model model = generate_plant_model("broadleaf", 7, 128);
    return model;
}

const crossed_billboard& broadleaf_billboard() {
    static const crossed_billboard billboard = bake_crossed_billboard(broadleaf(), {k_resolution, 4});
    return billboard;
}

TEST(crossed_billboard,
     is_two_crossing_quads_with_one_billboard_submesh_and_an_atlas_with_its_facing_views) {
    const crossed_billboard& b = broadleaf_billboard();
    ASSERT_EQ(b.mesh.triangle_count(), 4u);
    ASSERT_EQ(b.mesh.vertices.size(), 8u);
    ASSERT_EQ(b.mesh.submeshes.size(), 1u);
    EXPECT_EQ(b.mesh.submeshes[0].material, material_kind::billboard);
    EXPECT_EQ(b.mesh.submeshes[0].index_count, 12u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(b.mesh.vertices[i].normal, glm::vec3(0.0f, 0.0f, 1.0f));
        EXPECT_EQ(b.mesh.vertices[i].position.z, 0.0f);
        // The first seventh of the atlas and the second: the rest holds the facing views.
        EXPECT_LE(b.mesh.vertices[i].uv.x, 1.0f / 7.0f + 1e-6f);
        EXPECT_EQ(b.mesh.vertices[4 + i].normal, glm::vec3(1.0f, 0.0f, 0.0f));
        EXPECT_EQ(b.mesh.vertices[4 + i].position.x, 0.0f);
        EXPECT_GE(b.mesh.vertices[4 + i].uv.x, 1.0f / 7.0f - 1e-6f);
        EXPECT_LE(b.mesh.vertices[4 + i].uv.x, 2.0f / 7.0f + 1e-6f);
    }
    // Each quad is centred on the trunk axis and spans the model's height.
    const mesh_data& full = broadleaf().lods[0];
    float min_y = full.vertices[0].position.y;
    float max_y = min_y;
    float reach_x = 0.0f;
    for (const vertex& v : full.vertices) {
        min_y = std::min(min_y, v.position.y);
        max_y = std::max(max_y, v.position.y);
        reach_x = std::max(reach_x, std::abs(v.position.x));
    }
    EXPECT_FLOAT_EQ(b.mesh.bounds_min.y, min_y);
    EXPECT_FLOAT_EQ(b.mesh.bounds_max.y, max_y);
    EXPECT_FLOAT_EQ(b.mesh.bounds_max.x, reach_x);
    EXPECT_FLOAT_EQ(b.mesh.bounds_min.x, -reach_x);
    // Front faces: counter-clockwise seen from the side the normal points to.
    for (std::size_t t = 0; t < 4; ++t) {
        const glm::vec3 a = b.mesh.vertices[b.mesh.indices[t * 3]].position;
        const glm::vec3 c = b.mesh.vertices[b.mesh.indices[t * 3 + 1]].position;
        const glm::vec3 d = b.mesh.vertices[b.mesh.indices[t * 3 + 2]].position;
        EXPECT_GT(glm::dot(glm::cross(c - a, d - a), b.mesh.vertices[b.mesh.indices[t * 3]].normal), 0.0f) << t;
    }
    EXPECT_EQ(b.albedo.width, 7 * k_resolution);
    EXPECT_EQ(b.albedo.height, k_resolution);
    EXPECT_EQ(b.normal.width, 7 * k_resolution);
    EXPECT_EQ(b.normal.height, k_resolution);
    EXPECT_THROW(bake_crossed_billboard(broadleaf(), {127, 1}), std::invalid_argument);
}

// A hand-made pair whose quads span x in [-3, 3] and z in [-5, 5], y in [1, 9].
mesh_data hand_made_pair() {
    mesh_data pair;
    const glm::vec3 z{0.0f, 0.0f, 1.0f}, x{1.0f, 0.0f, 0.0f};
    pair.vertices = {{{-3.0f, 1.0f, 0.0f}, z, {0.0f, 0.5f}}, {{3.0f, 1.0f, 0.0f}, z, {0.5f, 0.5f}},
                     {{3.0f, 9.0f, 0.0f}, z, {0.5f, 0.0f}},  {{-3.0f, 9.0f, 0.0f}, z, {0.0f, 0.0f}},
                     {{0.0f, 1.0f, 5.0f}, x, {0.5f, 0.5f}},  {{0.0f, 1.0f, -5.0f}, x, {1.0f, 0.5f}},
                     {{0.0f, 9.0f, -5.0f}, x, {1.0f, 0.0f}}, {{0.0f, 9.0f, 5.0f}, x, {0.5f, 0.0f}}};
    pair.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    pair.submeshes = {{0, 12, material_kind::billboard}};
    return pair;
}

void expect_near(glm::vec3 a, glm::vec3 b, const char* what) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], 1e-3f) << what << "[" << i << "]";
}

// The facing views' planes on the hand-made pair (half-width w = 5, the wider quad; y from 1 to
// 9, middle 5), by hand at 30 degrees (c = 0.8660, s = 0.5): the box projects along the tilted
// up axis (0, c, -s) to 4 c + 5 s = 5.9641 either side of the middle, so quad 0's plane starts
// at (0, 5, 0) - (5, 0, 0) - 5.9641 (0, c, -s) = (-5, -0.1651, 2.9821), runs 10 along x and
// 11.9282 along (0, c, -s) = (0, 10.3301, -5.9641), and faces (0, 0.5, 0.8660). At 0 degrees
// the crossed quads, widened to 5.
TEST(crossed_billboard, its_facing_views_are_the_quads_tilted_back_by_their_elevations) {
    const mesh_data pair = hand_made_pair();
    std::array<billboard_plane, k_crossed_billboard_quads> planes;
    for (std::size_t q = 0; q < 2; ++q)
        planes[q] = {pair.vertices[4 * q].position,
                     pair.vertices[4 * q + 1].position - pair.vertices[4 * q].position,
                     pair.vertices[4 * q + 3].position - pair.vertices[4 * q].position};
    ASSERT_EQ(k_facing_elevations_deg[3], 30.0f);
    const billboard_plane steep = facing_view_plane(planes, 0, 3);
    expect_near(steep.origin, {-5.0f, -0.1651f, 2.9821f}, "origin");
    expect_near(steep.axis_u, {10.0f, 0.0f, 0.0f}, "axis_u");
    expect_near(steep.axis_v, {0.0f, 10.3301f, -5.9641f}, "axis_v");
    expect_near(steep.normal(), {0.0f, 0.5f, 0.8660f}, "normal");
    // Quad 1 (seen from +x, u along -z) the same turned a quarter: its tilted up axis leans away
    // from +x.
    const billboard_plane side = facing_view_plane(planes, 1, 3);
    expect_near(side.origin, {2.9821f, -0.1651f, 5.0f}, "side origin");
    expect_near(side.axis_u, {0.0f, 0.0f, -10.0f}, "side axis_u");
    expect_near(side.axis_v, {-5.9641f, 10.3301f, 0.0f}, "side axis_v");
    expect_near(side.normal(), {0.8660f, 0.5f, 0.0f}, "side normal");
    const billboard_plane level = facing_view_plane(planes, 0, 0);
    expect_near(level.origin, {-5.0f, 1.0f, 0.0f}, "level origin");
    expect_near(level.axis_v, {0.0f, 8.0f, 0.0f}, "level axis_v");
    EXPECT_THROW(facing_view_plane(planes, 2, 0), std::invalid_argument);
    EXPECT_THROW(facing_view_plane(planes, 0, 4), std::invalid_argument);
}

// The facing billboard's mesh is the elevation-0 views' pair (the crossed pair widened to the
// wider quad's 5) reading the atlas's first two facing views (s from 2.5/7 by 0.5/7 each), its
// normals carrying the middle height 5 as y; its bounds hold every tilted quad turned about the
// trunk. By hand, the 30-degree view reaches farthest: its top corner (5, 5 + 5.9641 c, -5.9641 s)
// is sqrt(25 + 2.9821^2) = 5.8217 from the axis and 10.1651 high, its bottom edge 5 - 5.9641 c =
// -0.1651.
TEST(crossed_billboard, its_facing_billboard_is_the_widened_pair_with_the_bounds_its_views_sweep) {
    const mesh_data pair = hand_made_pair();
    const mesh_data facing = facing_billboard_mesh(pair);
    EXPECT_EQ(facing.indices, pair.indices);
    ASSERT_EQ(facing.vertices.size(), 8u);
    const std::array<glm::vec3, 8> corners{{{-5, 1, 0},
                                            {5, 1, 0},
                                            {5, 9, 0},
                                            {-5, 9, 0},
                                            {0, 1, 5},
                                            {0, 1, -5},
                                            {0, 9, -5},
                                            {0, 9, 5}}};
    const float a = 5.0f / 14.0f, b = 6.0f / 14.0f, c = 7.0f / 14.0f;
    const std::array<glm::vec2, 8> uvs{
        {{a, 1.0f}, {b, 1.0f}, {b, 0.0f}, {a, 0.0f}, {b, 1.0f}, {c, 1.0f}, {c, 0.0f}, {b, 0.0f}}};
    for (std::size_t i = 0; i < 8; ++i) {
        expect_near(facing.vertices[i].position, corners[i], "corner");
        EXPECT_NEAR(facing.vertices[i].uv.x, uvs[i].x, 1e-6f) << i;
        EXPECT_EQ(facing.vertices[i].uv.y, uvs[i].y) << i;
        expect_near(facing.vertices[i].normal, i < 4 ? glm::vec3(0, 5, 1) : glm::vec3(1, 5, 0),
                    "normal");
    }
    ASSERT_EQ(facing.submeshes.size(), 1u);
    EXPECT_EQ(facing.submeshes[0].material, material_kind::facing_billboard);
    expect_near(facing.bounds_min, {-5.8217f, -0.1651f, -5.8217f}, "bounds_min");
    expect_near(facing.bounds_max, {5.8217f, 10.1651f, 5.8217f}, "bounds_max");
    EXPECT_THROW(facing_billboard_mesh(mesh_data{}), std::invalid_argument);
    // The baked broadleaf's: its two quads, 4 triangles.
    EXPECT_EQ(facing_billboard_mesh(broadleaf_billboard().mesh).triangle_count(), 4u);
}

// A "table": a 2 m x 4 m leaf card standing in the x-y plane (y 0..4) under a 2 m x 2 m bark
// card lying at y = 4. Seen from elevation e the lying card shows 2 x 2 sin e of the view's
// 2 w x (4 cos e + 2 w sin e) frame (w = 1), nothing hiding it: a share 2 s / (4 c + 2 s) of
// the cell, 0 / 0.0657 / 0.1254 / 0.2240 at 0 / 8 / 16 / 30 degrees, from +z and from +x alike.
TEST(crossed_billboard, its_facing_views_see_the_plant_from_their_elevations) {
    plant_model table;
    table.name = "table";
    mesh_data& mesh = table.lods[0];
    const glm::vec3 z{0.0f, 0.0f, 1.0f}, y{0.0f, 1.0f, 0.0f};
    mesh.vertices = {{{-1, 0, 0}, z, {0, 1}}, {{1, 0, 0}, z, {1, 1}},  {{1, 4, 0}, z, {1, 0}},
                     {{-1, 4, 0}, z, {0, 0}}, {{-1, 4, 1}, y, {0, 1}}, {{1, 4, 1}, y, {1, 1}},
                     {{1, 4, -1}, y, {1, 0}}, {{-1, 4, -1}, y, {0, 0}}};
    mesh.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    mesh.submeshes = {{0, 6, material_kind::leaf}, {6, 6, material_kind::bark}};
    const auto solid = [](std::uint8_t r, std::uint8_t g) {
        return image_rgba8{
            2, 2,
            std::vector<std::uint8_t>{r, g, 40, 255, r, g, 40, 255, r, g, 40, 255, r, g, 40, 255}};
    };
    table.leaf_texture = solid(40, 200);
    table.bark_texture = solid(200, 40);
    constexpr std::uint32_t resolution = 256, cell = resolution / 2;  // each view cell x resolution
    const crossed_billboard b = bake_crossed_billboard(table, {resolution, 4});
    const std::array<double, 4> expected{0.0, 0.0657, 0.1254, 0.2240};
    for (std::size_t k = 0; k < 4; ++k)
        for (std::uint32_t q = 0; q < 2; ++q) {
            const std::uint32_t x0 = std::uint32_t(5 + 2 * k + q) * cell;  // after 2.5 R
            double bark =
                0.0;  // covered share of the bark colour: (r - 40) / 160 of a texel's coverage
            for (std::uint32_t ty = 0; ty < resolution; ++ty)
                for (std::uint32_t tx = 0; tx < cell; ++tx) {
                    const std::uint8_t* t = b.albedo.at(x0 + tx, ty);
                    bark +=
                        std::clamp((double(t[0]) - 40.0) / 160.0, 0.0, 1.0) * double(t[3]) / 255.0;
                }
            EXPECT_NEAR(bark / double(cell * resolution), expected[k], 0.006)
                << "elevation " << k << " quad " << q;
        }
}

TEST(crossed_billboard, each_quad_covers_a_plausible_share_of_its_image) {
    const crossed_billboard& b = broadleaf_billboard();
    for (std::uint32_t q = 0; q < 2; ++q) {
        std::size_t covered = 0;
        for (std::uint32_t y = 0; y < k_resolution; ++y)
            for (std::uint32_t x = 0; x < k_resolution; ++x) covered += b.albedo.at(q * k_resolution + x, y)[3] > 0;
        const double share = double(covered) / double(k_resolution * k_resolution);
        EXPECT_GT(share, 0.15) << "quad " << q;
        EXPECT_LT(share, 0.85) << "quad " << q;
    }
}

// An independent projection: the texel under each triangle's centroid, by the layout the header
// documents (quad 0 seen from +z with u along +x, quad 1 from +x with u along -z, t = 0 at the
// top), must be covered. Leaf triangles whose centroid falls on a transparent leaf texel and
// triangles smaller than a subsample may rightly leave it uncovered and are skipped.
TEST(crossed_billboard, matches_the_silhouette_of_the_projected_mesh) {
    const plant_model& model = broadleaf();
    const crossed_billboard& b = broadleaf_billboard();
    const mesh_data& full = model.lods[0];
    const glm::vec3 lo = b.mesh.bounds_min;
    const glm::vec3 hi = b.mesh.bounds_max;
    const float texel_area_x = (hi.x - lo.x) * (hi.y - lo.y) / float(k_resolution * k_resolution);
    const float texel_area_z = (hi.z - lo.z) * (hi.y - lo.y) / float(k_resolution * k_resolution);
    std::size_t checked = 0;
    std::size_t missed = 0;
    for (const submesh& sub : full.submeshes)
        for (std::uint32_t i = sub.first_index; i < sub.first_index + sub.index_count; i += 3) {
            const vertex& p = full.vertices[full.indices[i]];
            const vertex& q = full.vertices[full.indices[i + 1]];
            const vertex& r = full.vertices[full.indices[i + 2]];
            const glm::vec3 c = (p.position + q.position + r.position) / 3.0f;
            if (sub.material == material_kind::leaf) {
                const glm::vec2 uv = (p.uv + q.uv + r.uv) / 3.0f;
                const auto tx = std::uint32_t(std::fmod(uv.x, 1.0f) * float(model.leaf_texture.width));
                const auto ty = std::uint32_t(std::fmod(uv.y, 1.0f) * float(model.leaf_texture.height));
                if (model.leaf_texture.at(tx, ty)[3] < 192) continue;
            }
            const glm::vec3 n = glm::cross(q.position - p.position, r.position - p.position);
            const auto row = std::uint32_t((hi.y - c.y) / (hi.y - lo.y) * float(k_resolution));
            const std::uint32_t y = std::min(row, k_resolution - 1);
            if (0.5f * std::abs(n.z) > texel_area_x) {  // quad 0: x to the right
                const auto col = std::uint32_t((c.x - lo.x) / (hi.x - lo.x) * float(k_resolution));
                ++checked;
                missed += b.albedo.at(std::min(col, k_resolution - 1), y)[3] == 0;
            }
            if (0.5f * std::abs(n.x) > texel_area_z) {  // quad 1: -z to the right
                const auto col = std::uint32_t((hi.z - c.z) / (hi.z - lo.z) * float(k_resolution));
                ++checked;
                missed += b.albedo.at(k_resolution + std::min(col, k_resolution - 1), y)[3] == 0;
            }
        }
    EXPECT_GT(checked, 1000u);
    EXPECT_EQ(missed, 0u) << "of " << checked;
}

TEST(crossed_billboard, bakes_byte_identically_twice) {
    const crossed_billboard again = bake_crossed_billboard(broadleaf(), {k_resolution, 4});
    EXPECT_EQ(again.albedo.texels, broadleaf_billboard().albedo.texels);
    EXPECT_EQ(again.normal.texels, broadleaf_billboard().normal.texels);
    EXPECT_EQ(serialize_crossed_billboard(again), serialize_crossed_billboard(broadleaf_billboard()));
}

TEST(crossed_billboard, round_trips_through_the_bake_cache_byte_identically) {
    namespace fs = std::filesystem;
    const fs::path root = fs::temp_directory_path() / ("sylva_billboard_test_" + std::to_string(::getpid()));
    fs::remove_all(root);
    const std::vector<std::byte> bytes = serialize_crossed_billboard(broadleaf_billboard());
    {
        bake_cache cache(root);
        cache.store("billboards", 99, bytes);
    }
    bake_cache cache(root);
    const auto loaded = cache.load("billboards", 99);
    ASSERT_TRUE(loaded);
    const crossed_billboard back = deserialize_crossed_billboard(*loaded);
    EXPECT_EQ(serialize_crossed_billboard(back), bytes);
    EXPECT_EQ(back.albedo.texels, broadleaf_billboard().albedo.texels);
    EXPECT_EQ(back.mesh.indices, broadleaf_billboard().mesh.indices);
    fs::remove_all(root);

    std::vector<std::byte> truncated(bytes.begin(), bytes.end() - 5);
    EXPECT_THROW(deserialize_crossed_billboard(truncated), std::runtime_error);
    std::vector<std::byte> other_version = bytes;
    other_version[4] = std::byte(0xee);
    EXPECT_THROW(deserialize_crossed_billboard(other_version), std::runtime_error);
}

}  // namespace
}  // namespace sylva

namespace sylva {
namespace {

TEST(crossed_billboard, with_transfer_bakes_five_pages_that_round_trip) {
    // Every vertex unoccluded and facing up (a made-up transfer): T0 = pi * 0.282095 = 0.886
    // on the front, 0 behind, so covered texels encode 0.886 first and 0 ninth.
    const plant_model& model = broadleaf();
    radiance_transfer t;
    t.bands = 2;
    for (std::size_t v = 0; v < model.lods[0].vertices.size(); ++v) {
        t.front.insert(t.front.end(), {0.886227f, 0.0f, 0.0f, 0.0f});
        t.back.insert(t.back.end(), {0.0f, 0.0f, 0.0f, 0.0f});
    }
    const crossed_billboard b = bake_crossed_billboard(model, {32, 2}, &t);
    ASSERT_EQ(b.transfer_pages.size(), k_transfer_pages);
    std::size_t covered = 0;
    for (std::uint32_t y = 0; y < b.albedo.height; ++y)
        for (std::uint32_t x = 0; x < b.albedo.width; ++x)
            if (b.albedo.at(x, y)[3] == 255) {
                ++covered;
                // A mean over subsamples of fronts (0.886) and leaf backs seen first (0).
                const float seen = decode_transfer(b.transfer_pages[0].at(x, y)[0]);
                EXPECT_GE(seen, -0.005f);
                EXPECT_LE(seen, 0.8910f);
                // The other side's first coefficient is the complement: 0.886 - seen.
                EXPECT_NEAR(decode_transfer(b.transfer_pages[2].at(x, y)[1]), 0.886227f - seen,
                            0.011f);
                EXPECT_EQ(b.transfer_pages[1].at(x, y)[0],
                          encode_transfer(0.0f));  // coefficient 4: 2 bands
            }
    EXPECT_GT(covered, 100u);
    const crossed_billboard back = deserialize_crossed_billboard(serialize_crossed_billboard(b));
    ASSERT_EQ(back.transfer_pages.size(), k_transfer_pages);
    EXPECT_EQ(back.transfer_pages[0].texels, b.transfer_pages[0].texels);
    EXPECT_TRUE(broadleaf_billboard().transfer_pages.empty());
}

}  // namespace
}  // namespace sylva
