#include "models/bake/crossed_billboard.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "models/cache/bake_cache.h"
#include "models/cache/billboard_io.h"
#include "models/generate/plant_library.h"
#include "models/bake/transfer_pages.h"

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

TEST(crossed_billboard, is_two_crossing_quads_with_one_billboard_submesh_and_a_two_slot_atlas) {
    const crossed_billboard& b = broadleaf_billboard();
    ASSERT_EQ(b.mesh.triangle_count(), 4u);
    ASSERT_EQ(b.mesh.vertices.size(), 8u);
    ASSERT_EQ(b.mesh.submeshes.size(), 1u);
    EXPECT_EQ(b.mesh.submeshes[0].material, material_kind::billboard);
    EXPECT_EQ(b.mesh.submeshes[0].index_count, 12u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(b.mesh.vertices[i].normal, glm::vec3(0.0f, 0.0f, 1.0f));
        EXPECT_EQ(b.mesh.vertices[i].position.z, 0.0f);
        EXPECT_LE(b.mesh.vertices[i].uv.x, 0.5f);
        EXPECT_EQ(b.mesh.vertices[4 + i].normal, glm::vec3(1.0f, 0.0f, 0.0f));
        EXPECT_EQ(b.mesh.vertices[4 + i].position.x, 0.0f);
        EXPECT_GE(b.mesh.vertices[4 + i].uv.x, 0.5f);
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
    EXPECT_EQ(b.albedo.width, 2 * k_resolution);
    EXPECT_EQ(b.albedo.height, k_resolution);
    EXPECT_EQ(b.normal.width, 2 * k_resolution);
    EXPECT_EQ(b.normal.height, k_resolution);
}

// The facing billboard draws the pair with its own material (its vertex shader shows one quad
// turned to the eye), and its bounds are the circle the wider quad sweeps as the plant turns
// about its trunk: on a hand-made pair whose quads span x in [-3, 3] and z in [-5, 5], y in
// [1, 9], the box is [-5, 5] in x and z and [1, 9] in y.
TEST(crossed_billboard, its_facing_billboard_is_the_pair_with_the_bounds_either_quad_sweeps) {
    mesh_data pair;
    const glm::vec3 z{0.0f, 0.0f, 1.0f}, x{1.0f, 0.0f, 0.0f};
    pair.vertices = {{{-3.0f, 1.0f, 0.0f}, z, {0.0f, 1.0f}}, {{3.0f, 1.0f, 0.0f}, z, {0.5f, 1.0f}},
                     {{3.0f, 9.0f, 0.0f}, z, {0.5f, 0.0f}},  {{-3.0f, 9.0f, 0.0f}, z, {0.0f, 0.0f}},
                     {{0.0f, 1.0f, 5.0f}, x, {0.5f, 1.0f}},  {{0.0f, 1.0f, -5.0f}, x, {1.0f, 1.0f}},
                     {{0.0f, 9.0f, -5.0f}, x, {1.0f, 0.0f}}, {{0.0f, 9.0f, 5.0f}, x, {0.5f, 0.0f}}};
    pair.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    pair.submeshes = {{0, 12, material_kind::billboard}};
    const mesh_data facing = facing_billboard_mesh(pair);
    EXPECT_EQ(facing.indices, pair.indices);
    ASSERT_EQ(facing.vertices.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(facing.vertices[i].uv, pair.vertices[i].uv);
    ASSERT_EQ(facing.submeshes.size(), 1u);
    EXPECT_EQ(facing.submeshes[0].material, material_kind::facing_billboard);
    EXPECT_EQ(facing.bounds_min, glm::vec3(-5.0f, 1.0f, -5.0f));
    EXPECT_EQ(facing.bounds_max, glm::vec3(5.0f, 9.0f, 5.0f));
    EXPECT_THROW(facing_billboard_mesh(mesh_data{}), std::invalid_argument);
    // The baked broadleaf's: its two quads, 4 triangles.
    EXPECT_EQ(facing_billboard_mesh(broadleaf_billboard().mesh).triangle_count(), 4u);
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
