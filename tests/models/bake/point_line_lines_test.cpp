// The line half of the point and line bake (Deussen 2002 §4.2): which elements become lines,
// and their length l and error ε_l against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "models/generate/plant_mesh_builder.h"
#include "models/bake/point_line_bake.h"
#include "point_line_fixtures.h"

namespace sylva {
namespace {

using namespace sylva::testing;

constexpr glm::vec3 k_across{0.0f, 0.0f, 1.0f};

// A blade strip along `spine` with constant half width.
void add_blade(plant_mesh_builder& out, std::vector<glm::vec3> spine, float half_width,
               std::uint32_t index) {
    const std::vector<float> widths(spine.size(), half_width);
    const std::vector<glm::vec3> across(spine.size(), k_across);
    add_strip(out, spine, widths, across, uv_rect{}, {index, 0, part_kind::blade, index});
}

point_line_model bake_foliage(plant_mesh_builder&& foliage, plant_mesh_builder&& bark = {}) {
    return bake_point_lines(model_of(assemble_plant_mesh(std::move(bark), std::move(foliage))));
}

std::vector<const lod_part*> line_parts(const point_line_model& m) {
    std::vector<const lod_part*> parts;
    for (const lod_part& p : m.parts)
        if (p.primitive == lod_primitive::lines) parts.push_back(&p);
    return parts;
}

TEST(point_line_lines, straight_blades_give_one_line_each_and_their_summed_length) {
    plant_mesh_builder foliage;
    // Three straight blades, three cross-sections each: lengths 0.5, 0.7 and 1.0, half widths
    // 0.01, 0.02, 0.015. l = 2.2; ε_l = the widest half width, 0.02.
    add_blade(foliage, {{0, 0, 0}, {0, 0.25f, 0}, {0, 0.5f, 0}}, 0.01f, 0);
    add_blade(foliage, {{1, 0, 0}, {1.35f, 0, 0}, {1.7f, 0, 0}}, 0.02f, 1);
    add_blade(foliage, {{0, 0, 2}, {0.6f, 0.8f, 2}}, 0.015f, 2);
    const point_line_model m = bake_foliage(std::move(foliage));
    ASSERT_EQ(m.parts.size(), 1u);
    const lod_part& p = m.parts[0];
    EXPECT_EQ(p.primitive, lod_primitive::lines);
    EXPECT_EQ(p.kind, part_kind::blade);
    EXPECT_EQ(p.line_count, 3u);
    EXPECT_NEAR(p.line_length_m, 2.2f, 1e-5f);
    EXPECT_NEAR(p.line_error_m, 0.02f, 1e-5f);
    EXPECT_EQ(p.point_count, 0u);
    EXPECT_EQ(p.triangle_count, 10u);
    float summed = 0.0f;
    for (std::uint32_t i = 0; i < p.line_count; ++i)
        summed += glm::length(m.lines[2 * (p.first_line + i) + 1].position -
                              m.lines[2 * (p.first_line + i)].position);
    EXPECT_NEAR(summed, 2.2f, 1e-5f);
}

TEST(point_line_lines, a_needle_card_runs_base_to_tip_with_its_half_width_as_error) {
    plant_mesh_builder foliage;
    const card needle{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.4f, 0.1f};
    add_card(foliage, needle, uv_rect{}, {3, 3, part_kind::needle, 3});
    const point_line_model m = bake_foliage(std::move(foliage));
    ASSERT_EQ(m.parts.size(), 1u);
    const lod_part& p = m.parts[0];
    ASSERT_EQ(p.line_count, 1u);
    EXPECT_NEAR(p.line_length_m, 0.4f, 1e-6f);
    EXPECT_NEAR(p.line_error_m, 0.05f, 1e-6f);
    const vertex& a = m.lines[2 * p.first_line];
    const vertex& b = m.lines[2 * p.first_line + 1];
    EXPECT_NEAR(std::min(a.position.y, b.position.y), 0.0f, 1e-6f);
    EXPECT_NEAR(std::max(a.position.y, b.position.y), 0.4f, 1e-6f);
    EXPECT_NEAR(std::abs(a.normal.z), 1.0f, 1e-5f);  // the card's face
}

// A blade bent at its middle cross-section by s across a half width h = 0.05: spine (0, 0, 0),
// (s, 1, 0), (0, 2, 0), the blade's width along z.
struct bent_blade {
    float bend;
    point_line_model bake() const {
        plant_mesh_builder foliage;
        add_blade(foliage, {{0, 0, 0}, {bend, 1, 0}, {0, 2, 0}}, 0.05f, 0);
        return bake_foliage(std::move(foliage));
    }
};

TEST(point_line_lines, a_gently_bent_blade_keeps_one_line_whose_error_is_the_bow) {
    // s = 0.025 is within half the width of the chord: one line, base to tip (l = 2), and the
    // farthest vertex, (s, 1, ±h), is sqrt(s² + h²) from it.
    const point_line_model m = bent_blade{0.025f}.bake();
    const lod_part& p = m.parts.at(0);
    EXPECT_EQ(p.line_count, 1u);
    EXPECT_NEAR(p.line_length_m, 2.0f, 1e-5f);
    EXPECT_NEAR(p.line_error_m, std::sqrt(0.025f * 0.025f + 0.05f * 0.05f), 1e-5f);
}

TEST(point_line_lines, a_strongly_bent_blade_splits_at_the_bend) {
    // s = 0.15 is beyond half the width: two lines through the bend, l = 2 sqrt(1 + s²), and
    // every vertex is h = 0.05 from them.
    const point_line_model m = bent_blade{0.15f}.bake();
    const lod_part& p = m.parts.at(0);
    EXPECT_EQ(p.line_count, 2u);
    EXPECT_NEAR(p.line_length_m, 2.0f * std::sqrt(1.0f + 0.15f * 0.15f), 1e-5f);
    EXPECT_NEAR(p.line_error_m, 0.05f, 1e-5f);
}

void add_stem(plant_mesh_builder& out, glm::vec3 from, glm::vec3 to, float radius,
              std::uint32_t branch, std::uint8_t level) {
    const glm::vec3 tangent = glm::normalize(to - from);
    const glm::vec3 normal = glm::normalize(glm::cross(tangent, glm::vec3{0.3f, 0.1f, 1.0f}));
    const std::vector<tube_ring> rings{{from, tangent, normal, radius},
                                       {0.5f * (from + to), tangent, normal, radius},
                                       {to, tangent, normal, radius}};
    add_tube(out, rings, 6, 0.1f, {branch, level, part_kind::bark, 0});
}

// Plant about 4 m tall. Trunk: 3 m, diameter 0.4 (elongation 7.5, but 10 % of the plant: points).
// Level-1 bough, 1.5 m, diameter 0.04 (1 %): lines. Level-2 twig, 0.5 m, diameter 0.02: lines.
// Level-2 stub, 0.05 m, diameter 0.02 (elongation 2.5): points.
TEST(point_line_lines, thin_long_stems_become_lines_and_the_trunk_points) {
    plant_mesh_builder bark;
    add_stem(bark, {0, 0, 0}, {0, 3, 0}, 0.2f, 0, 0);
    add_stem(bark, {0, 2, 0}, {1.5f, 2, 0}, 0.02f, 1, 1);
    add_stem(bark, {0, 3, 0}, {0, 3.5f, 0}, 0.01f, 2, 2);
    add_stem(bark, {0, 1, 0}, {0.05f, 1, 0}, 0.01f, 3, 2);
    plant_mesh_builder foliage;
    add_card(foliage, {{0, 3.5f, 0}, {0, 1, 0}, {1, 0, 0}, 0.5f, 0.5f}, uv_rect{},
             {2, 3, part_kind::leaf, 2});
    const point_line_model m = bake_foliage(std::move(foliage), std::move(bark));
    const std::vector<const lod_part*> lines = line_parts(m);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0]->material, material_kind::bark);
    EXPECT_EQ(lines[0]->triangle_count, 2u * 2u * 6u * 2u);  // two stems, two segments of six sides
    EXPECT_EQ(lines[0]->line_count, 2u);
    EXPECT_NEAR(lines[0]->line_length_m, 2.0f, 1e-4f);
    // A hexagonal tube's vertices are its radius from the axis: ε_l is the bough's radius.
    EXPECT_NEAR(lines[0]->line_error_m, 0.02f, 1e-4f);
    for (std::uint32_t i = 0; i < 2 * lines[0]->line_count; ++i) {
        const vertex& v = m.lines[2 * lines[0]->first_line + i];
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
    }
    std::uint32_t bark_points = 0;
    for (const lod_part& p : m.parts)
        if (p.primitive == lod_primitive::points && p.material == material_kind::bark)
            bark_points += p.triangle_count;
    EXPECT_EQ(bark_points, 2u * 2u * 6u * 2u);  // trunk and stub
}

// No triangle records (an imported model): a square leaf stays points, a 1 m x 5 cm strip of the
// same material is long and thin and becomes one line.
TEST(point_line_lines, an_imported_model_finds_its_long_thin_elements) {
    mesh_data mesh;
    add_quad(mesh, {0, 0, 0}, {0.3f, 0, 0}, {0, 0, 0.3f});
    add_quad(mesh, {2, 0, 0}, {0.05f, 0, 0}, {0, 1, 0});
    close_submesh(mesh, 0, material_kind::leaf);
    const point_line_model m = bake_point_lines(model_of(std::move(mesh)));
    ASSERT_EQ(m.parts.size(), 2u);
    const std::vector<const lod_part*> lines = line_parts(m);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0]->line_count, 1u);
    EXPECT_NEAR(lines[0]->line_length_m, 1.0f, 1e-5f);
    EXPECT_NEAR(lines[0]->line_error_m, 0.025f, 1e-5f);
    EXPECT_TRUE(m.triangles.parts.empty());
}

TEST(point_line_lines, lines_are_shuffled_but_cover_every_blade) {
    plant_mesh_builder foliage;
    for (std::uint32_t i = 0; i < 40; ++i)
        add_blade(foliage, {{float(i), 0, 0}, {float(i), 0.5f, 0}, {float(i), 1, 0}}, 0.01f, i);
    const point_line_model m = bake_foliage(std::move(foliage));
    const lod_part& p = m.parts.at(0);
    ASSERT_EQ(p.line_count, 40u);
    std::vector<int> blade_of_line;
    for (std::uint32_t i = 0; i < p.line_count; ++i)
        blade_of_line.push_back(int(std::lround(m.lines[2 * i].position.x)));
    std::vector<int> ordered = blade_of_line;
    std::sort(ordered.begin(), ordered.end());
    for (int i = 0; i < 40; ++i) EXPECT_EQ(ordered[std::size_t(i)], i);
    EXPECT_NE(blade_of_line, ordered) << "lines not shuffled";
}

}  // namespace
}  // namespace sylva
