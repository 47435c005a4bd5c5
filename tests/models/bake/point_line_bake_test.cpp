#include "models/bake/point_line_bake.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "models/generate/plant_library.h"
#include "models/cache/point_line_io.h"
#include "point_line_fixtures.h"

namespace sylva {
namespace {

using namespace sylva::testing;

constexpr triangle_part k_leaf_part{0, 1, part_kind::leaf, 0};

// n x n unit squares side by side in the xz plane, each two equal triangles.
plant_model grid_of_squares(int n, image_rgba8 leaf = solid_texture(40, 140, 30)) {
    mesh_data mesh;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            add_quad(mesh, {float(i) * 1.5f, 0.0f, float(j) * 1.5f}, {1.0f, 0.0f, 0.0f},
                     {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f}, {1.0f, 1.0f}, &k_leaf_part);
    close_submesh(mesh, 0, material_kind::leaf);
    return model_of(std::move(mesh), std::move(leaf));
}

const lod_part& only_part(const point_line_model& m) {
    EXPECT_EQ(m.parts.size(), 1u);
    return m.parts.front();
}

TEST(point_line_bake, two_equal_triangles_get_two_points_each) {
    const point_line_model m = bake_point_lines(grid_of_squares(1));
    const lod_part& p = only_part(m);
    EXPECT_EQ(p.primitive, lod_primitive::points);
    EXPECT_TRUE(p.stratified);
    EXPECT_EQ(p.triangle_count, 2u);
    EXPECT_EQ(p.point_count, 4u);
    EXPECT_EQ(std::vector<std::uint32_t>(m.points_after.begin() + p.first_after,
                                         m.points_after.begin() + p.first_after + 3),
              (std::vector<std::uint32_t>{4, 2, 0}));
    EXPECT_FLOAT_EQ(p.area_m2, 1.0f);
    EXPECT_NEAR(glm::length(p.center - glm::vec3{0.5f, 0.0f, 0.5f}), 0.0f, 1e-5f);
}

TEST(point_line_bake, a_stratified_part_counts_two_points_per_remaining_triangle) {
    const point_line_model m = bake_point_lines(grid_of_squares(6));
    const lod_part& p = only_part(m);
    ASSERT_TRUE(p.stratified);
    const std::uint32_t n = p.triangle_count;
    ASSERT_EQ(n, 72u);
    for (std::uint32_t t = 0; t <= n; ++t)
        EXPECT_EQ(m.points_after[p.first_after + t], 2 * (n - t)) << t;
}

// 25 triangles each of areas a, 2a, 4a, 8a: the ratio 8 is above similar_area_ratio, so the
// 2n points go by area, and each class's count must match its share.
TEST(point_line_bake, area_weighted_counts_follow_the_area) {
    mesh_data mesh;
    const std::array<float, 4> k_class_area{0.5f, 1.0f, 2.0f, 4.0f};
    for (int i = 0; i < 100; ++i) {
        const float leg =
            std::sqrt(2.0f * k_class_area[std::size_t(i % 4)]);  // right isosceles triangle
        const glm::vec3 o{float(i) * 4.0f, 0.0f, 0.0f};
        add_triangle(mesh, o, o + glm::vec3{leg, 0.0f, 0.0f}, o + glm::vec3{0.0f, 0.0f, leg},
                     &k_leaf_part);
    }
    close_submesh(mesh, 0, material_kind::leaf);
    const point_line_model m = bake_point_lines(model_of(std::move(mesh)));
    const lod_part& p = only_part(m);
    ASSERT_FALSE(p.stratified);
    ASSERT_EQ(p.point_count, 200u);
    std::array<double, 4> observed{};
    for (std::uint32_t t = 0; t < p.triangle_count; ++t) {
        const std::size_t i = p.first_index + 3 * std::size_t(t);
        const glm::vec3 a = m.triangles.vertices[m.triangles.indices[i]].position;
        const float area =
            0.5f *
            glm::length(glm::cross(m.triangles.vertices[m.triangles.indices[i + 1]].position - a,
                                   m.triangles.vertices[m.triangles.indices[i + 2]].position - a));
        const auto [begin, end] = points_of(m, p, t);
        const double expected = 200.0 * area / 187.5;  // 2n a / A, A = 25 (0.5 + 1 + 2 + 4)
        EXPECT_LT(std::abs(double(end - begin) - expected), 1.0)
            << "triangle " << t << " area " << area;
        const auto cls = std::size_t(std::lround(std::log2(area / 0.5f)));
        observed[cls] += end - begin;
    }
    double chi_square = 0.0;
    for (std::size_t c = 0; c < 4; ++c) {
        const double expected = 200.0 * 25.0 * k_class_area[c] / 187.5;
        chi_square += (observed[c] - expected) * (observed[c] - expected) / expected;
    }
    // 3 degrees of freedom: the 0.1 % critical value of the chi-square distribution is 16.27.
    EXPECT_LT(chi_square, 16.27);
}

// Checks every point of every point part against its own triangle and the alpha test.
void expect_points_on_opaque_triangles(const point_line_model& m, const image_rgba8& leaf) {
    std::size_t checked = 0;
    for (const lod_part& p : m.parts) {
        if (p.primitive != lod_primitive::points) continue;
        for (std::uint32_t t = 0; t < p.triangle_count; ++t) {
            const std::size_t i = p.first_index + 3 * std::size_t(t);
            const vertex& a = m.triangles.vertices[m.triangles.indices[i]];
            const vertex& b = m.triangles.vertices[m.triangles.indices[i + 1]];
            const vertex& c = m.triangles.vertices[m.triangles.indices[i + 2]];
            const auto [begin, end] = points_of(m, p, t);
            for (std::uint32_t k = begin; k < end; ++k) {
                const vertex& point = m.points[k];
                const barycentric_fit fit =
                    fit_barycentric(point.position, a.position, b.position, c.position);
                EXPECT_GE(std::min({fit.weights.x, fit.weights.y, fit.weights.z}), -1e-4f)
                    << "point " << k;
                EXPECT_LT(fit.plane_distance, 1e-4f) << "point " << k;
                const glm::vec2 uv =
                    fit.weights.x * a.uv + fit.weights.y * b.uv + fit.weights.z * c.uv;
                EXPECT_LT(glm::length(uv - point.uv), 1e-4f) << "point " << k;
                if (p.material == material_kind::leaf) {
                    EXPECT_GE(reference_alpha(leaf, point.uv), 0.5f - 1e-4f) << "point " << k;
                }
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 0u);
}

TEST(point_line_bake, stratified_points_lie_on_their_triangle_and_an_opaque_texel) {
    const image_rgba8 leaf = checker_texture(32, 4);  // half the texels cut away, in 4 x 4 blocks
    const point_line_model m = bake_point_lines(grid_of_squares(4, leaf));
    ASSERT_TRUE(only_part(m).stratified);
    expect_points_on_opaque_triangles(m, leaf);
}

TEST(point_line_bake, area_weighted_points_lie_on_their_triangle_and_an_opaque_texel) {
    const image_rgba8 leaf = checker_texture(32, 4);
    mesh_data mesh;
    for (int i = 0; i < 12; ++i) {
        const float size = 0.2f + 0.3f * float(i);  // areas 0.04 .. 13.7: not similar
        add_quad(mesh, {float(i) * 5.0f, 0.0f, 0.0f}, {size, 0.0f, 0.0f}, {0.0f, size, 0.0f},
                 {0.0f, 0.0f}, {1.0f, 1.0f}, &k_leaf_part);
    }
    close_submesh(mesh, 0, material_kind::leaf);
    const point_line_model m = bake_point_lines(model_of(std::move(mesh), leaf));
    ASSERT_FALSE(only_part(m).stratified);
    expect_points_on_opaque_triangles(m, leaf);
}

TEST(point_line_bake, area_counts_only_what_the_alpha_test_keeps) {
    // 64 x 64 texels, the left half opaque: a unit quad mapped over it keeps half its area. A
    // second quad mapped onto the transparent half alone keeps nothing and is dropped, as is a
    // zero-area triangle.
    image_rgba8 leaf = checker_texture(64, 32);
    for (std::uint32_t y = 0; y < 64; ++y)
        for (std::uint32_t x = 0; x < 64; ++x) leaf.at(x, y)[3] = x < 32 ? 255 : 0;
    mesh_data mesh;
    add_quad(mesh, {0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f},
             {1.0f, 1.0f}, &k_leaf_part);
    add_quad(mesh, {3.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.6f, 0.1f},
             {0.9f, 0.9f}, &k_leaf_part);
    add_triangle(mesh, {5.0f, 0.0f, 0.0f}, {6.0f, 0.0f, 0.0f}, {7.0f, 0.0f, 0.0f}, &k_leaf_part);
    close_submesh(mesh, 0, material_kind::leaf);
    const point_line_model m = bake_point_lines(model_of(std::move(mesh), leaf));
    const lod_part& p = only_part(m);
    EXPECT_EQ(p.triangle_count, 2u);
    EXPECT_NEAR(p.area_m2, 0.5f, 0.08f);
    EXPECT_NEAR(p.center.x, 0.25f, 0.05f);  // the opaque half's centroid
    for (const std::uint32_t index : m.triangles.indices) EXPECT_LT(index, 4u);
}

TEST(point_line_bake, each_part_holds_a_shuffled_permutation_of_its_triangles) {
    mesh_data mesh;
    const triangle_part bark{0, 0, part_kind::bark, 0};
    for (int i = 0; i < 20; ++i)  // stubby bark boxes' sides: points
        add_quad(mesh, {float(i), 0.0f, 0.0f}, {0.5f, 0.0f, 0.0f}, {0.0f, 0.5f, 0.0f}, {0.0f, 0.0f},
                 {1.0f, 1.0f}, &bark);
    close_submesh(mesh, 0, material_kind::bark);
    const auto leaf_first = std::uint32_t(mesh.indices.size());
    for (int i = 0; i < 30; ++i)
        add_quad(mesh, {float(i), 2.0f, 0.0f}, {0.5f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.5f}, {0.0f, 0.0f},
                 {1.0f, 1.0f}, &k_leaf_part);
    close_submesh(mesh, leaf_first, material_kind::leaf);
    const plant_model model = model_of(mesh);
    const point_line_model m = bake_point_lines(model);
    ASSERT_EQ(m.parts.size(), 2u);
    for (const lod_part& p : m.parts) {
        const bool is_bark = p.material == material_kind::bark;
        const std::vector<triangle_key> original =
            triangle_keys(mesh.indices, is_bark ? 0 : leaf_first, is_bark ? 40 : 60);
        const std::vector<triangle_key> baked =
            triangle_keys(m.triangles.indices, p.first_index, p.triangle_count);
        EXPECT_EQ(sorted(baked), sorted(original));
        EXPECT_NE(baked, original) << "not shuffled";
        for (std::uint32_t t = 0; t < p.triangle_count; ++t)
            EXPECT_EQ(m.triangles.parts[p.first_index / 3 + t].kind,
                      is_bark ? part_kind::bark : part_kind::leaf);
    }
    ASSERT_EQ(m.triangles.submeshes.size(), 2u);
    EXPECT_EQ(m.triangles.submeshes[0].first_index, m.parts[0].first_index);
    EXPECT_EQ(m.triangles.submeshes[1].material, m.parts[1].material);
}

TEST(point_line_bake, the_same_seed_gives_the_same_bytes_and_another_seed_another_order) {
    point_line_settings settings;
    settings.seed = 11;
    const std::vector<std::byte> a = serialize_point_line_model(
        bake_point_lines(generate_plant_model("broadleaf", 3, 64), settings));
    const std::vector<std::byte> b = serialize_point_line_model(
        bake_point_lines(generate_plant_model("broadleaf", 3, 64), settings));
    EXPECT_TRUE(a == b);
    settings.seed = 12;
    const point_line_model other =
        bake_point_lines(generate_plant_model("broadleaf", 3, 64), settings);
    const point_line_model first = deserialize_point_line_model(a);
    ASSERT_EQ(other.parts.size(), first.parts.size());
    EXPECT_NE(other.triangles.indices, first.triangles.indices);
    for (std::size_t i = 0; i < first.parts.size(); ++i)
        EXPECT_EQ(sorted(triangle_keys(other.triangles.indices, other.parts[i].first_index,
                                       other.parts[i].triangle_count)),
                  sorted(triangle_keys(first.triangles.indices, first.parts[i].first_index,
                                       first.parts[i].triangle_count)));
}

TEST(point_line_bake, petals_are_more_important_than_leaves) {
    const point_line_model m = bake_point_lines(generate_plant_model("flower", 5, 64));
    float petal = 0.0f;
    float leaf = 100.0f;
    for (const lod_part& p : m.parts) {
        if (p.kind == part_kind::petal) petal = std::max(petal, p.importance);
        if (p.kind == part_kind::leaf) leaf = std::min(leaf, p.importance);
    }
    EXPECT_GE(petal, point_line_settings{}.petal_importance);
    EXPECT_FLOAT_EQ(leaf, 1.0f);
}

// An imported model (no triangle records) with six green leaves and one red one of the same size:
// colour analysis classes the red one as a petal, with the petals' importance.
TEST(point_line_bake, a_distinct_colour_makes_an_imported_leaf_important) {
    image_rgba8 atlas = solid_texture(0, 0, 0);
    atlas.width = 2;
    atlas.height = 1;
    atlas.texels = {30, 110, 20, 255, 200, 20, 30, 255};  // green texel, red texel
    mesh_data mesh;
    for (int i = 0; i < 7; ++i) {
        const glm::vec2 uv =
            i < 6 ? glm::vec2{0.25f, 0.5f} : glm::vec2{0.75f, 0.5f};  // texel centres
        add_quad(mesh, {float(i), 0.0f, 0.0f}, {0.5f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.5f}, uv, uv);
    }
    close_submesh(mesh, 0, material_kind::leaf);
    const plant_model model = model_of(std::move(mesh), atlas);
    const point_line_model automatic = bake_point_lines(model);
    ASSERT_EQ(automatic.parts.size(), 2u);
    std::map<part_kind, const lod_part*> by_kind;
    for (const lod_part& p : automatic.parts) by_kind[p.kind] = &p;
    ASSERT_TRUE(by_kind.contains(part_kind::petal) && by_kind.contains(part_kind::leaf));
    EXPECT_EQ(by_kind[part_kind::petal]->triangle_count, 2u);
    EXPECT_FLOAT_EQ(by_kind[part_kind::petal]->importance, 4.0f);
    EXPECT_FLOAT_EQ(by_kind[part_kind::leaf]->importance, 1.0f);

    point_line_settings manual;
    manual.automatic_importance = false;
    const point_line_model plain = bake_point_lines(model, manual);
    ASSERT_EQ(plain.parts.size(), 1u);
    EXPECT_FLOAT_EQ(plain.parts[0].importance, 1.0f);
}

TEST(point_line_bake, octree_depth_one_splits_into_cells_that_partition_the_triangles) {
    const plant_model model = generate_plant_model("broadleaf", 2, 64);
    point_line_settings settings;
    const point_line_model whole = bake_point_lines(model, settings);
    settings.octree_depth = 1;
    const point_line_model split = bake_point_lines(model, settings);
    ASSERT_EQ(whole.cells.size(), 1u);
    EXPECT_GE(split.cells.size(), 4u);
    EXPECT_LE(split.cells.size(), 8u);
    std::uint32_t next_part = 0;
    for (const lod_cell& cell : split.cells) {
        EXPECT_EQ(cell.first_part, next_part);
        EXPECT_GE(cell.part_count, 1u);
        EXPECT_LE(cell.part_count, k_max_cell_parts);
        next_part += cell.part_count;
        for (std::uint32_t i = cell.first_part; i < cell.first_part + cell.part_count; ++i) {
            const lod_part& p = split.parts[i];
            for (std::uint32_t t = 0; t < p.triangle_count; ++t) {
                glm::vec3 centroid{0.0f};
                for (int k = 0; k < 3; ++k)
                    centroid +=
                        split.triangles
                            .vertices[split.triangles
                                          .indices[p.first_index + 3 * t + std::uint32_t(k)]]
                            .position /
                        3.0f;
                EXPECT_TRUE(glm::all(glm::greaterThanEqual(centroid, cell.bounds_min - 1e-5f)) &&
                            glm::all(glm::lessThanEqual(centroid, cell.bounds_max + 1e-5f)));
            }
        }
    }
    EXPECT_EQ(next_part, split.parts.size());
    EXPECT_EQ(sorted(triangle_keys(split.triangles.indices, 0,
                                   std::uint32_t(split.triangles.triangle_count()))),
              sorted(triangle_keys(whole.triangles.indices, 0,
                                   std::uint32_t(whole.triangles.triangle_count()))));
    EXPECT_EQ(split.triangles.triangle_count(), model.lods[0].triangle_count());
}

TEST(point_line_bake, rejects_an_octree_deeper_than_three) {
    point_line_settings settings;
    settings.octree_depth = 4;
    EXPECT_THROW(bake_point_lines(grid_of_squares(1), settings), std::invalid_argument);
}

// The presets bake into models the reader accepts, with the primitives their species call for.
TEST(point_line_bake, presets_bake_to_valid_models_of_the_expected_primitives) {
    const std::map<std::string, std::pair<part_kind, lod_primitive>> k_expected = {
        {"broadleaf", {part_kind::leaf, lod_primitive::points}},
        {"conifer", {part_kind::needle, lod_primitive::lines}},
        {"grass", {part_kind::blade, lod_primitive::lines}},
        {"flower", {part_kind::petal, lod_primitive::points}},
    };
    for (const auto& [preset, expected] : k_expected) {
        SCOPED_TRACE(preset);
        const plant_model model = generate_plant_model(preset, 9, 64);
        const point_line_model m = bake_point_lines(model);
        EXPECT_NO_THROW(deserialize_point_line_model(serialize_point_line_model(m)));
        EXPECT_EQ(m.triangles.triangle_count(), model.lods[0].triangle_count());
        std::map<part_kind, lod_primitive> primitive_of;
        for (const lod_part& p : m.parts) {
            primitive_of[p.kind] = p.primitive;
            if (p.primitive == lod_primitive::points) {
                EXPECT_EQ(p.point_count, 2 * p.triangle_count);
            } else {
                EXPECT_GT(p.line_length_m, 0.0f);
            }
        }
        ASSERT_TRUE(primitive_of.contains(expected.first));
        EXPECT_EQ(primitive_of.at(expected.first), expected.second);
    }
}

}  // namespace
}  // namespace sylva
