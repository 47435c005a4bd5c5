// Luft, Balzer & Deussen 2007 (models/bake/implicit_illumination.h) at hand-computed values: the
// density of Eq. 2 and Eq. 3, the ambient transfer function of Eq. 4, the iso-surface of one
// generator (a sphere of radius ρ·sqrt(1 − sqrt(τ))), the realigned normal and k_a stored as its
// length, the defaults from the model's size, and the whole bake on a generated tree.
#include "models/bake/implicit_illumination.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <tbb/global_control.h>

#include "models/bake/billboard_cloud.h"
#include "models/bake/point_line_bake.h"
#include "models/generate/plant_library.h"
#include "models/random.h"

namespace sylva {
namespace {

TEST(implicit_illumination, one_generator_density_is_eq2) {
    // D = (1 − (d/ρ)²)²: d = ρ/2 gives (3/4)² = 0.5625; d = 0 gives 1; d >= ρ gives 0.
    EXPECT_FLOAT_EQ(generator_density(0.25f, 1.0f), 0.5625f);
    EXPECT_FLOAT_EQ(generator_density(0.0f, 2.0f), 1.0f);
    EXPECT_FLOAT_EQ(generator_density(4.0f, 2.0f), 0.0f);
    EXPECT_FLOAT_EQ(generator_density(9.0f, 2.0f), 0.0f);
}

TEST(implicit_illumination, the_field_sums_its_generators_less_tau_eq3) {
    // Generators at x = 0 and x = 1, ρ = 2, τ = 0.3. At x = 0.5 each is 0.5 away: s² = 1/16,
    // D = (15/16)² = 0.87890625, F = 2 × 0.87890625 − 0.3 = 1.4578125.
    const implicit_field field({{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}}, 2.0f, 0.3f);
    EXPECT_FLOAT_EQ(field.value({0.5f, 0.0f, 0.0f}), 1.4578125f);
    // At x = 3: the first is beyond ρ, the second 2 away (exactly ρ): F = −τ.
    EXPECT_FLOAT_EQ(field.value({3.0f, 0.0f, 0.0f}), -0.3f);
    // The level set's outward normal on the axis beyond both generators points along +x.
    const glm::vec3 n = field.outward_normal({2.5f, 0.0f, 0.0f});
    EXPECT_NEAR(n.x, 1.0f, 1e-6f);
    EXPECT_THROW(implicit_field({{0.0f, 0.0f, 0.0f}}, 0.0f, 0.1f), std::invalid_argument);
    EXPECT_THROW(implicit_field({{0.0f, 0.0f, 0.0f}}, 1.0f, -0.1f), std::invalid_argument);
}

TEST(implicit_illumination, the_ambient_coefficient_is_eq4) {
    // k_a,min = 0.2, d_min = 2, n = 2: d <= 0 → 1; d = 1 → 0.2 + 0.8·(1/2)² = 0.4; d >= 2 → 0.2.
    EXPECT_FLOAT_EQ(ambient_coefficient(-1.0f, 0.2f, 2.0f, 2.0f), 1.0f);
    EXPECT_FLOAT_EQ(ambient_coefficient(0.0f, 0.2f, 2.0f, 2.0f), 1.0f);
    EXPECT_FLOAT_EQ(ambient_coefficient(1.0f, 0.2f, 2.0f, 2.0f), 0.4f);
    EXPECT_FLOAT_EQ(ambient_coefficient(2.0f, 0.2f, 2.0f, 2.0f), 0.2f);
    EXPECT_FLOAT_EQ(ambient_coefficient(3.0f, 0.2f, 2.0f, 2.0f), 0.2f);
    // n = 1, d = 0.5: 0.2 + 0.8 · 0.75 = 0.8; n = 1/3 darkens more slowly (Figure 4).
    EXPECT_FLOAT_EQ(ambient_coefficient(0.5f, 0.2f, 2.0f, 1.0f), 0.8f);
    EXPECT_GT(ambient_coefficient(0.5f, 0.2f, 2.0f, 1.0f / 3.0f), 0.8f);
}

TEST(implicit_illumination, one_generator_gives_a_sphere_with_radial_normals) {
    // ρ = 1, τ = 1/4: D = τ where 1 − s² = 1/2, a sphere of radius sqrt(1/2) = 0.7071.
    const implicit_field field({{0.0f, 0.0f, 0.0f}}, 1.0f, 0.25f);
    const float cell = 0.05f;
    const iso_surface surface = extract_iso_surface(field, cell);
    ASSERT_GT(surface.positions.size(), 500u);
    ASSERT_EQ(surface.normals.size(), surface.positions.size());
    for (std::size_t i = 0; i < surface.positions.size(); ++i) {
        const glm::vec3 p = surface.positions[i];
        EXPECT_NEAR(glm::length(p), std::sqrt(0.5f), 0.5f * cell) << "vertex " << i;
        EXPECT_GT(glm::dot(surface.normals[i], glm::normalize(p)), 0.999f) << "vertex " << i;
    }
}

TEST(implicit_illumination, a_vertex_takes_the_nearest_surface_normal_and_ka_as_its_length) {
    const implicit_field field({{0.0f, 0.0f, 0.0f}}, 1.0f, 0.25f);
    // Samples 0.05 apart from −1.05: the inside vertex below sits on one (x = 27 cells).
    const density_grid grid = sample_density(field, 0.05f);
    const iso_surface surface = extract_iso_surface(field, grid);
    implicit_settings s;
    s.source = ambient_source::density;  // the paper's d_v = F(v)
    s.tau = 0.25f;
    s.ka_min = 0.2f;
    s.d_min = 1.0f;
    s.exponent = 1.0f;
    mesh_data mesh;
    mesh.vertices = {{{0.3f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {}},   // inside
                     {{0.0f, 0.0f, 2.0f}, {0.0f, 1.0f, 0.0f}, {}}};  // beyond ρ
    mesh_data kept = mesh;
    apply_implicit_illumination(mesh, grid, surface, s);
    // Inside: F = (1 − 0.09)² − 0.25 = 0.5781, k_a = 0.2 + 0.8·(1 − 0.5781) = 0.53752; the
    // nearest surface vertex lies on +x, whose normal is +x.
    const float f = (1.0f - 0.09f) * (1.0f - 0.09f) - 0.25f;
    EXPECT_NEAR(glm::length(mesh.vertices[0].normal), 0.2f + 0.8f * (1.0f - f), 1e-4f);
    EXPECT_GT(glm::normalize(mesh.vertices[0].normal).x, 0.99f);
    // Beyond every generator: F = −τ < 0, k_a = 1, the normal of the nearest point (+z).
    EXPECT_NEAR(glm::length(mesh.vertices[1].normal), 1.0f, 1e-6f);
    EXPECT_GT(glm::normalize(mesh.vertices[1].normal).z, 0.99f);
    // blend 0 keeps the original direction and still stores k_a.
    s.blend = 0.0f;
    apply_implicit_illumination(kept, grid, surface, s);
    EXPECT_NEAR(glm::normalize(kept.vertices[0].normal).y, 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(kept.vertices[0].normal), glm::length(mesh.vertices[0].normal), 1e-6f);
}

// ambient_source::depth: Eq. 4 of the depth below the iso-surface instead of F.
TEST(implicit_illumination, the_depth_below_the_surface_feeds_eq4) {
    // The sphere of radius sqrt(1/2) above, sampled 0.05 apart from −1.05: on the +x axis the
    // samples x = 0.70 and 0.75 hold D = 0.51² = 0.2601 and 0.4375² = 0.19140625, so marching
    // cubes puts a vertex where D = τ = 1/4: x = 0.70 + 0.05·0.0101/0.06869375 = 0.707351.
    const implicit_field field({{0.0f, 0.0f, 0.0f}}, 1.0f, 0.25f);
    const density_grid grid = sample_density(field, 0.05f);
    const iso_surface surface = extract_iso_surface(field, grid);
    EXPECT_FLOAT_EQ(depth_below_surface(0.5f, 0.04f), 0.2f);    // inside: positive
    EXPECT_FLOAT_EQ(depth_below_surface(-0.1f, 0.04f), -0.2f);  // outside: negative
    EXPECT_FLOAT_EQ(depth_below_surface(0.0f, 0.04f),
                    -0.2f);  // on F = 0: not inside (Eq. 4: k_a 1)
    implicit_settings s;
    ASSERT_EQ(s.source, ambient_source::depth);  // the default
    EXPECT_EQ(ambient_source_named("depth"), ambient_source::depth);
    EXPECT_EQ(ambient_source_named("density"), ambient_source::density);
    s.tau = 0.25f;
    s.ka_min = 0.2f;
    s.depth_min_m = 1.0f;
    s.d_min = 1e6f;  // the density's d_min: unused by the depth
    s.exponent = 1.0f;
    mesh_data mesh;
    mesh.vertices = {{{0.3f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {}},   // inside, 0.407351 deep
                     {{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {}},   // the centre, ~0.7071 deep
                     {{0.0f, 0.0f, 2.0f}, {0.0f, 1.0f, 0.0f}, {}}};  // outside
    apply_implicit_illumination(mesh, grid, surface, s);
    // k_a = 0.2 + 0.8·(1 − 0.407351) = 0.674119; at the centre 0.2 + 0.8·(1 − 0.7071) = 0.4343
    // (the nearest of the surface's vertices, each within half a cell of the sphere: ±0.02).
    EXPECT_NEAR(glm::length(mesh.vertices[0].normal), 0.674119f, 2e-3f);
    EXPECT_NEAR(glm::length(mesh.vertices[1].normal), 0.4343f, 0.02f);
    EXPECT_NEAR(glm::length(mesh.vertices[2].normal), 1.0f, 1e-6f);
    // The default d_min for depth: twice the generators' median depth, here the one generator at
    // the centre: 2·sqrt(1/2) = 1.4142 (±2 half cells).
    EXPECT_NEAR(default_depth_min({{0.0f, 0.0f, 0.0f}}, grid, surface, 0.25f), 1.4142f, 0.05f);
    // No generator inside (τ above every density): at least one cell.
    EXPECT_FLOAT_EQ(default_depth_min({{0.0f, 0.0f, 0.0f}}, grid, iso_surface{}, 0.25f), 0.05f);
}

TEST(implicit_illumination, the_sampled_density_interpolates_between_its_samples) {
    // One generator at 0, ρ = 1, samples 0.5 apart from −1.5: x = 0 holds D = 1, x = 0.5 holds
    // D = (1 − 0.25)² = 0.5625 (Eq. 2), so x = 0.25 reads their mean 0.78125 (Eq. 2 itself gives
    // (1 − 0.0625)² = 0.87890625 there: the grid's error at a generator's peak, ρ/2 cells).
    const implicit_field one({{0.0f, 0.0f, 0.0f}}, 1.0f, 0.0f);
    const density_grid grid = sample_density(one, 0.5f);
    EXPECT_EQ(grid.size, glm::ivec3(7));
    EXPECT_NEAR(grid.density_at({0.0f, 0.0f, 0.0f}), 1.0f, 1e-6f);
    EXPECT_NEAR(grid.density_at({0.25f, 0.0f, 0.0f}), 0.78125f, 1e-6f);
    EXPECT_NEAR(one.density({0.25f, 0.0f, 0.0f}), 0.87890625f, 1e-6f);
    EXPECT_EQ(grid.density_at({5.0f, 0.0f, 0.0f}), 0.0f);  // beyond the grid: no generator reaches
    // A crown-like cloud at the bake's ρ/4 cells, against the foliage's own median density:
    // 2 % root-mean-square, 15 % at worst (beside a few generators' peaks: a lone peak of 1 reads
    // 0.91 from corners √3·ρ/8 away).
    rng r(7, 0);
    std::vector<glm::vec3> points;
    for (int i = 0; i < 3000; ++i) {
        const glm::vec3 p(r.uniform() * 2.0f - 1.0f, r.uniform() * 2.0f - 1.0f, r.uniform() * 2.0f - 1.0f);
        if (glm::length(p) < 1.0f) points.push_back(3.0f * p);
    }
    const implicit_field crown(points, 0.6f, 0.0f);
    const density_grid sampled = sample_density(crown, 0.6f / 4.0f);
    std::vector<float> own;
    for (const glm::vec3& p : points) own.push_back(crown.density(p));
    std::nth_element(own.begin(), own.begin() + std::ptrdiff_t(own.size() / 2), own.end());
    const float median = own[own.size() / 2];
    float worst = 0.0f;
    double squares = 0.0;
    constexpr int k_queries = 4000;
    for (int i = 0; i < k_queries; ++i) {
        const glm::vec3 q(r.uniform() * 7.0f - 3.5f, r.uniform() * 7.0f - 3.5f, r.uniform() * 7.0f - 3.5f);
        const float e = std::abs(sampled.density_at(q) - crown.density(q));
        worst = std::max(worst, e);
        squares += double(e) * double(e);
    }
    const double rms = std::sqrt(squares / k_queries);
    std::printf("median density %.3f: rms error %.4f, worst %.4f\n", median, rms, worst);
    EXPECT_LT(rms, 0.02 * median);
    EXPECT_LT(worst, 0.15f * median);
}

TEST(implicit_illumination, generators_are_foliage_centroids_and_defaults_follow_the_size) {
    mesh_data mesh;
    mesh.vertices = {{{0, 0, 0}, {0, 1, 0}, {}}, {{3, 0, 0}, {0, 1, 0}, {}}, {{0, 3, 0}, {0, 1, 0}, {}},
                     {{10, 0, 0}, {0, 1, 0}, {}}, {{13, 0, 0}, {0, 1, 0}, {}}, {{10, 3, 0}, {0, 1, 0}, {}}};
    mesh.indices = {0, 1, 2, 3, 4, 5, 0, 2, 1};
    mesh.submeshes = {{0, 6, material_kind::leaf}, {6, 3, material_kind::bark}};
    const std::vector<glm::vec3> g = foliage_generators(mesh, 1.0f, 7);
    ASSERT_EQ(g.size(), 2u);  // the bark triangle is no generator
    EXPECT_EQ(g[0], glm::vec3(1.0f, 1.0f, 0.0f));
    EXPECT_EQ(g[1], glm::vec3(11.0f, 1.0f, 0.0f));
    // Their box's diagonal is 10: ρ = 0.2 × 5 = 1. They are 10 apart, so each sees only itself:
    // m = 1 (read from the samples: each generator sits on one), τ = 1/4, d_min = 2 (1 − 1/4) =
    // 3/2. Given values are kept.
    const implicit_settings d = implicit_defaults(g, {});
    EXPECT_FLOAT_EQ(d.rho_m, 1.0f);
    EXPECT_FLOAT_EQ(d.tau, 0.25f);
    EXPECT_FLOAT_EQ(d.d_min, 1.5f);
    implicit_settings given;
    given.rho_m = 2.0f;
    given.tau = 0.5f;
    given.d_min = 0.1f;
    EXPECT_EQ(implicit_defaults(g, given), given);
}

TEST(implicit_illumination, a_generated_tree_is_darker_inside_and_bakes_the_same_on_one_thread) {
    plant_model tree = generate_plant_model("broadleaf", 5, 64);
    plant_model again = tree;
    const implicit_report r = bake_implicit_illumination(tree, implicit_settings{});
    // The depth's d_min filled in: the typical leaf a metre or so deep in a crown ~9 m across.
    EXPECT_GT(r.used.depth_min_m, 1.0f);
    EXPECT_LT(r.used.depth_min_m, 5.0f);
    EXPECT_GT(r.generators, 100u);
    EXPECT_GT(r.surface_vertices, 100u);
    EXPECT_GT(r.mean_ka, r.used.ka_min);
    EXPECT_LT(r.mean_ka, 0.95f);
    for (const mesh_data& level : tree.lods)
        for (const vertex& v : level.vertices) {
            ASSERT_GE(glm::length(v.normal), r.used.ka_min - 1e-4f);
            ASSERT_LE(glm::length(v.normal), 1.0f + 1e-4f);
        }
    {
        // One thread (the field's sums, OpenVDB's meshing and the nearest-vertex lookups all run
        // on TBB): the same normals to the bit.
        const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        bake_implicit_illumination(again, implicit_settings{});
    }
    for (std::size_t i = 0; i < tree.lods[0].vertices.size(); ++i)
        ASSERT_EQ(tree.lods[0].vertices[i].normal, again.lods[0].vertices[i].normal) << "vertex " << i;
}

// §3.2–3.3 reach the line rung (Deussen 2002 §4.2's lines of needles): each line vertex takes the
// realigned normal and k_a of the nearest vertex of its needle, so lines are darker inside the
// crown, as the mesh is; a plain conifer's lines keep unit normals.
TEST(implicit_illumination, line_samples_carry_the_realigned_normal_and_ka) {
    plant_model conifer = generate_plant_model("conifer", 3, 64);
    const point_line_model plain = bake_point_lines(conifer);
    ASSERT_GT(plain.lines.size(), 100u);
    for (const vertex& v : plain.lines) ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
    const implicit_report r = bake_implicit_illumination(conifer, implicit_settings{});
    const point_line_model lit = bake_point_lines(conifer);
    ASSERT_EQ(lit.lines.size(), plain.lines.size());
    double sum = 0.0;
    for (const vertex& v : lit.lines) {
        const float ka = glm::length(v.normal);
        ASSERT_GE(ka, r.used.ka_min - 1e-4f);
        ASSERT_LE(ka, 1.0f + 1e-4f);
        sum += ka;
    }
    // The lines' mean k_a follows the mesh's (they sample its vertices), well below 1.
    EXPECT_LT(sum / double(lit.lines.size()), 0.95);
    EXPECT_NEAR(sum / double(lit.lines.size()), r.mean_ka, 0.1);
}

// Eq. 1's ambient term k_a·I_a on the pre-lit cloud page (light_factor): with ambient 0.3 and the
// sun straight on, k_a = 0.5 gives 0.5·0.3 + 0.7 = 0.85, in shadow 0.15.
TEST(implicit_illumination, the_pre_lit_page_scales_its_ambient_by_ka) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    EXPECT_FLOAT_EQ(light_factor(up, up, 1.0f, 0.3f, 0.5f), 0.85f);
    EXPECT_FLOAT_EQ(light_factor(up, up, 0.0f, 0.3f, 0.5f), 0.15f);
    EXPECT_FLOAT_EQ(light_factor(up, up, 0.0f, 0.3f), 0.3f);  // a plain model: k_a = 1
}

}  // namespace
}  // namespace sylva
