#include "models/bake/billboard_bake.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace sylva {
namespace {

// An 8 x 8 texel plane over x, y in [0, 8] seen from +z: one texel per model unit, row 0 at
// y = 8 (the top).
constexpr billboard_plane k_plane{{0.0f, 0.0f, 0.0f}, {8.0f, 0.0f, 0.0f}, {0.0f, 8.0f, 0.0f}};

billboard_bake_settings small_settings() {
    billboard_bake_settings s;
    s.width = 8;
    s.height = 8;
    s.supersampling = 4;
    return s;
}

image_rgba8 solid(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) {
    image_rgba8 image;
    image.width = 2;
    image.height = 2;
    image.texels.resize(16);
    for (std::size_t i = 0; i < 16; i += 4) {
        image.texels[i] = r;
        image.texels[i + 1] = g;
        image.texels[i + 2] = b;
        image.texels[i + 3] = a;
    }
    return image;
}

// Appends an axis-aligned rectangle [x0, x1] x [y0, y1] at depth z as two triangles, counter-
// clockwise seen from +z unless `facing_away`, with vertex normals `normal`, as one submesh.
void add_rect(mesh_data& mesh, float x0, float y0, float x1, float y1, float z, material_kind material,
              glm::vec3 normal = {0.0f, 0.0f, 1.0f}, bool facing_away = false) {
    const auto base = std::uint32_t(mesh.vertices.size());
    mesh.vertices.push_back({{x0, y0, z}, normal, {0.0f, 0.0f}});
    mesh.vertices.push_back({{x1, y0, z}, normal, {1.0f, 0.0f}});
    mesh.vertices.push_back({{x1, y1, z}, normal, {1.0f, 1.0f}});
    mesh.vertices.push_back({{x0, y1, z}, normal, {0.0f, 1.0f}});
    const auto first = std::uint32_t(mesh.indices.size());
    const std::uint32_t front[6] = {0, 1, 2, 0, 2, 3};
    const std::uint32_t back[6] = {0, 2, 1, 0, 3, 2};
    for (std::uint32_t i : facing_away ? back : front) mesh.indices.push_back(base + i);
    mesh.submeshes.push_back({first, 6, material});
}

struct scene {
    mesh_data mesh;
    image_rgba8 leaf = solid(40, 160, 30, 255);
    image_rgba8 bark = solid(200, 100, 50, 255);
    billboard_image bake(const billboard_bake_settings& s = small_settings(), const billboard_plane& p = k_plane,
                         std::span<const std::uint32_t> triangles = {}) const {
        return bake_billboard({&mesh, &leaf, &bark, triangles}, p, s);
    }
};

std::uint32_t covered_at(const billboard_image& image, std::uint32_t x, std::uint32_t y) {
    return image.covered[std::size_t(y) * image.albedo.width + x];
}

TEST(billboard_bake, an_opaque_quad_covers_exactly_its_texels_with_its_colour) {
    scene s;
    // x 2..5, y 1..7: columns 2..4, rows 8-7 = 1 .. 8-1-1 = 6 -> 3 x 6 = 18 texels, all 16/16.
    add_rect(s.mesh, 2.0f, 1.0f, 5.0f, 7.0f, 0.0f, material_kind::bark);
    const billboard_image image = s.bake();
    int full = 0;
    int partial = 0;
    for (std::uint32_t y = 0; y < 8; ++y)
        for (std::uint32_t x = 0; x < 8; ++x) {
            const std::uint32_t c = covered_at(image, x, y);
            const bool inside = x >= 2 && x <= 4 && y >= 1 && y <= 6;
            EXPECT_EQ(c, inside ? 16u : 0u) << x << "," << y;
            full += c == 16;
            partial += c > 0 && c < 16;
            const std::uint8_t* a = image.albedo.at(x, y);
            EXPECT_EQ(a[3], inside ? 255 : 0);
            if (inside) {
                EXPECT_EQ(a[0], 200);
                EXPECT_EQ(a[1], 100);
                EXPECT_EQ(a[2], 50);
            }
        }
    EXPECT_EQ(full, 18);
    EXPECT_EQ(partial, 0);
}

TEST(billboard_bake, the_image_is_upright_and_unmirrored_for_the_viewer_on_the_normal_side) {
    scene s;
    add_rect(s.mesh, 0.0f, 7.0f, 1.0f, 8.0f, 0.0f, material_kind::bark);  // upper-left unit square
    const billboard_image image = s.bake();
    EXPECT_EQ(covered_at(image, 0, 0), 16u);
    EXPECT_EQ(covered_at(image, 7, 0), 0u);
    EXPECT_EQ(covered_at(image, 0, 7), 0u);
    EXPECT_EQ(k_plane.normal(), glm::vec3(0.0f, 0.0f, 1.0f));

    // Seen from behind (back_side), the same square is in the upper-right corner, and the bark
    // quad, now facing away, is culled: only a leaf (double-sided) shows there.
    scene leaf;
    add_rect(leaf.mesh, 0.0f, 7.0f, 1.0f, 8.0f, 0.0f, material_kind::leaf);
    const billboard_image back = leaf.bake(small_settings(), back_side(k_plane));
    EXPECT_EQ(covered_at(back, 7, 0), 16u);
    EXPECT_EQ(covered_at(back, 0, 0), 0u);
    EXPECT_EQ(s.bake(small_settings(), back_side(k_plane)).covered, std::vector<std::uint16_t>(64, 0));
}

TEST(billboard_bake, a_half_texel_edge_covers_eight_of_sixteen_subsamples) {
    scene s;
    add_rect(s.mesh, 3.0f, 2.0f, 3.5f, 3.0f, 0.0f, material_kind::bark);  // left half of texel (3, 5)
    const billboard_image image = s.bake();
    EXPECT_EQ(covered_at(image, 3, 5), 8u);
    EXPECT_EQ(image.albedo.at(3, 5)[3], 128);  // round(255 * 8 / 16)
    EXPECT_EQ(image.normal.at(3, 5)[3], 128);
    std::uint32_t total = 0;
    for (std::uint16_t c : image.covered) total += c;
    EXPECT_EQ(total, 8u);
}

// Two rectangles meeting on a vertical line through subsample centres (x = 2.125 is the centre
// of subsample column 8), and their shared diagonals through centres too: every subsample is
// covered by exactly one of them, whichever is baked alone.
TEST(billboard_bake, edges_through_subsample_centres_are_counted_once) {
    scene left;
    scene right;
    scene both;
    add_rect(left.mesh, 0.125f, 0.125f, 2.125f, 4.125f, 0.0f, material_kind::bark);
    add_rect(right.mesh, 2.125f, 0.125f, 4.125f, 4.125f, 0.0f, material_kind::bark);
    add_rect(both.mesh, 0.125f, 0.125f, 4.125f, 4.125f, 0.0f, material_kind::bark);
    const billboard_image l = left.bake();
    const billboard_image r = right.bake();
    const billboard_image b = both.bake();
    std::uint32_t sum_l = 0;
    std::uint32_t sum_r = 0;
    std::uint32_t sum_b = 0;
    for (std::size_t i = 0; i < b.covered.size(); ++i) {
        sum_l += l.covered[i];
        sum_r += r.covered[i];
        sum_b += b.covered[i];
    }
    // 16 x 16 subsample centres lie in [0.125, 4.125)^2 under the top-left rule's half-open
    // ownership; the two halves split them 8 + 8 columns.
    EXPECT_EQ(sum_b, 256u);
    EXPECT_EQ(sum_l, 128u);
    EXPECT_EQ(sum_r, 128u);
}

TEST(billboard_bake, the_surface_nearest_the_viewer_wins_in_either_order) {
    for (bool near_first : {true, false}) {
        scene s;
        s.bark = solid(255, 0, 0, 255);
        // Near (z = 1) is bark; far (z = -1) is an opaque leaf (green).
        if (near_first) add_rect(s.mesh, 0.0f, 0.0f, 8.0f, 8.0f, 1.0f, material_kind::bark);
        add_rect(s.mesh, 0.0f, 0.0f, 8.0f, 8.0f, -1.0f, material_kind::leaf);
        if (!near_first) add_rect(s.mesh, 0.0f, 0.0f, 8.0f, 8.0f, 1.0f, material_kind::bark);
        const billboard_image image = s.bake();
        EXPECT_EQ(image.albedo.at(4, 4)[0], 255) << near_first;
        EXPECT_EQ(image.albedo.at(4, 4)[1], 0) << near_first;
        EXPECT_FLOAT_EQ(image.depth[4 * 8 + 4], 1.0f);
    }
}

TEST(billboard_bake, transparent_leaf_texels_neither_cover_nor_hide_what_is_behind) {
    scene s;
    s.leaf = solid(40, 160, 30, 0);
    add_rect(s.mesh, 0.0f, 0.0f, 8.0f, 8.0f, 1.0f, material_kind::leaf);
    const billboard_image alone = s.bake();
    EXPECT_EQ(alone.covered, std::vector<std::uint16_t>(64, 0));
    for (std::size_t i = 3; i < alone.albedo.texels.size(); i += 4) EXPECT_EQ(alone.albedo.texels[i], 0);

    add_rect(s.mesh, 0.0f, 0.0f, 4.0f, 8.0f, -1.0f, material_kind::bark);  // behind, left half
    const billboard_image with_bark = s.bake();
    EXPECT_EQ(covered_at(with_bark, 1, 1), 16u);
    EXPECT_EQ(with_bark.albedo.at(1, 1)[0], 200);  // the bark's colour, not the leaf's
    EXPECT_EQ(covered_at(with_bark, 6, 1), 0u);

    s.leaf = solid(40, 160, 30, 255);  // the control: an opaque leaf covers and hides
    const billboard_image opaque = s.bake();
    EXPECT_EQ(covered_at(opaque, 6, 1), 16u);
    EXPECT_EQ(opaque.albedo.at(1, 1)[1], 160);
}

// A quad facing the viewer with normal (0, 0, 1) = the plane's normal encodes as
// round((0 * 0.5 + 0.5) * 255) = 128, 128 and round(1 * 255) = 255.
TEST(billboard_bake, the_normal_map_encodes_the_nearest_normal_turned_toward_the_viewer) {
    scene s;
    add_rect(s.mesh, 0.0f, 0.0f, 4.0f, 8.0f, 0.0f, material_kind::bark);
    // A leaf card wound away from the viewer, normal pointing away: seen from its back, its
    // normal is turned around as the leaf shader does.
    add_rect(s.mesh, 4.0f, 0.0f, 8.0f, 8.0f, 0.0f, material_kind::leaf, {0.0f, 0.0f, -1.0f}, true);
    const billboard_image image = s.bake();
    for (std::uint32_t x : {1u, 6u}) {
        const std::uint8_t* n = image.normal.at(x, 3);
        EXPECT_EQ(n[0], 128) << x;
        EXPECT_EQ(n[1], 128) << x;
        EXPECT_EQ(n[2], 255) << x;
        EXPECT_EQ(n[3], 255) << x;
    }
    scene tilted;  // a normal along +x encodes (255, 128, 128)
    add_rect(tilted.mesh, 0.0f, 0.0f, 8.0f, 8.0f, 0.0f, material_kind::bark, {1.0f, 0.0f, 0.0f});
    const billboard_image tilted_image = tilted.bake();  // n points into it: keep it alive
    const std::uint8_t* n = tilted_image.normal.at(2, 2);
    EXPECT_EQ(n[0], 255);
    EXPECT_EQ(n[1], 128);
    EXPECT_EQ(n[2], 128);
}

TEST(billboard_bake, uncovered_texels_take_the_nearest_covered_colour) {
    scene s;
    add_rect(s.mesh, 0.0f, 0.0f, 2.0f, 8.0f, 0.0f, material_kind::bark);
    billboard_bake_settings settings = small_settings();
    settings.dilation_texels = 2;
    const billboard_image image = s.bake(settings);
    for (std::uint32_t x = 2; x < 8; ++x) {  // every texel right of the quad: the bark colour, alpha 0
        const std::uint8_t* a = image.albedo.at(x, 4);
        EXPECT_EQ(a[0], 200) << x;
        EXPECT_EQ(a[1], 100) << x;
        EXPECT_EQ(a[2], 50) << x;
        EXPECT_EQ(a[3], 0) << x;
        EXPECT_EQ(image.normal.at(x, 4)[2], 255) << x;
    }
}

TEST(billboard_bake, a_triangle_subset_bakes_only_those_triangles) {
    scene s;
    add_rect(s.mesh, 0.0f, 0.0f, 4.0f, 8.0f, 0.0f, material_kind::bark);  // triangles 0, 1
    add_rect(s.mesh, 4.0f, 0.0f, 8.0f, 8.0f, 0.0f, material_kind::leaf);  // triangles 2, 3
    const std::uint32_t leaf_only[] = {2, 3};
    const billboard_image image = s.bake(small_settings(), k_plane, leaf_only);
    EXPECT_EQ(covered_at(image, 1, 1), 0u);
    EXPECT_EQ(covered_at(image, 6, 1), 16u);
    EXPECT_EQ(image.albedo.at(6, 1)[1], 160);
}

TEST(billboard_bake, rejects_bad_planes_and_missing_inputs) {
    scene s;
    add_rect(s.mesh, 0.0f, 0.0f, 1.0f, 1.0f, 0.0f, material_kind::bark);
    EXPECT_THROW(s.bake(small_settings(), {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}), std::invalid_argument);
    EXPECT_THROW(s.bake(small_settings(), {{0, 0, 0}, {0, 0, 0}, {0, 1, 0}}), std::invalid_argument);
    EXPECT_THROW(bake_billboard({&s.mesh, nullptr, &s.bark, {}}, k_plane, small_settings()), std::invalid_argument);
    const std::uint32_t out_of_range[] = {5};
    EXPECT_THROW(s.bake(small_settings(), k_plane, out_of_range), std::invalid_argument);
}

}  // namespace
}  // namespace sylva

namespace sylva {
namespace {

// A transfer with one receiver per vertex of `mesh`: front coefficient i of vertex v is
// front_value(v, i), back is its negative (so the two sides are told apart).
radiance_transfer linear_transfer(const mesh_data& mesh) {
    radiance_transfer t;
    t.bands = 3;
    for (const vertex& v : mesh.vertices)
        for (int i = 0; i < 9; ++i) {
            t.front.push_back(0.1f * float(i) + 0.05f * v.position.x);
            t.back.push_back(-(0.1f * float(i) + 0.05f * v.position.x));
        }
    return t;
}

TEST(billboard_bake, transfer_is_interpolated_over_the_covered_subsamples_seen_side_first) {
    scene s;
    add_rect(s.mesh, 0.0f, 0.0f, 4.0f, 8.0f, 0.0f, material_kind::bark);
    // A leaf seen from its back: its back transfer is the side the viewer sees.
    add_rect(s.mesh, 4.0f, 0.0f, 8.0f, 8.0f, 0.0f, material_kind::leaf, {0.0f, 0.0f, -1.0f}, true);
    const radiance_transfer t = linear_transfer(s.mesh);
    const billboard_image image =
        bake_billboard({&s.mesh, &s.leaf, &s.bark, {}, &t}, k_plane, small_settings());
    ASSERT_EQ(image.transfer.size(), 64u * k_billboard_transfer_floats);
    auto at = [&](std::uint32_t x, std::uint32_t y, std::size_t i) {
        return image.transfer[(std::size_t(y) * 8 + x) * k_billboard_transfer_floats + i];
    };
    // Texel (1, 3) covers x in [1, 2]: Gouraud interpolation of 0.05 x gives 0.05 * 1.5 there.
    EXPECT_NEAR(at(1, 3, 2), 0.2f + 0.075f, 1e-5f);
    EXPECT_NEAR(at(1, 3, 9 + 2), -(0.2f + 0.075f), 1e-5f);
    // Texel (6, 3) shows the leaf's back: seen first is its back vector, x in [6, 7].
    EXPECT_NEAR(at(6, 3, 4), -(0.4f + 0.325f), 1e-5f);
    EXPECT_NEAR(at(6, 3, 9 + 4), 0.4f + 0.325f, 1e-5f);
}

TEST(billboard_bake, transfer_must_match_the_mesh) {
    scene s;
    add_rect(s.mesh, 0.0f, 0.0f, 8.0f, 8.0f, 0.0f, material_kind::bark);
    radiance_transfer t = linear_transfer(s.mesh);
    t.front.resize(9);
    t.back.resize(9);
    EXPECT_THROW(bake_billboard({&s.mesh, &s.leaf, &s.bark, {}, &t}, k_plane, small_settings()),
                 std::invalid_argument);
}

}  // namespace
}  // namespace sylva
