// The LoDF bake (models/bake/lodf_bake.h): leaves found and collapsed into the structure
// lod/lodf.h walks, without new vertices, on generated plants.
#include "models/bake/lodf_bake.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <set>

#include "models/bake/lodf_leaves.h"
#include "models/generate/plant_library.h"

namespace sylva {
namespace {

// The cost by hand: two leaves of 1 m² two metres apart, facing the same way, made into a quad of
// their 2 m², move 2·1·1/(1+1)·2 = 2 m³ of area-metres; at one place but at right angles, their
// 2 m² turn with a rim of side √2 through the whole (1 − 0) of the angle: 2·√2 ≈ 2.828; a quad
// of 1 m² instead of 2 loses 1 m² at side √2: another 1.414.
TEST(lodf_bake, collapse_cost_is_area_moved_turned_and_resized) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f), side(1.0f, 0.0f, 0.0f);
    EXPECT_FLOAT_EQ(lodf_collapse_cost(1.0f, {0, 0, 0}, up, 1.0f, {2, 0, 0}, up, 2.0f), 2.0f);
    EXPECT_NEAR(lodf_collapse_cost(1.0f, {0, 0, 0}, up, 1.0f, {0, 0, 0}, side, 2.0f), 2.0 * std::sqrt(2.0), 1e-5);
    EXPECT_NEAR(lodf_collapse_cost(1.0f, {0, 0, 0}, up, 1.0f, {2, 0, 0}, up, 1.0f), 2.0 + std::sqrt(2.0), 1e-5);
    // A small leaf beside a large one moves little area: 2·0.1·1/1.1·2 ≈ 0.364.
    EXPECT_NEAR(lodf_collapse_cost(0.1f, {0, 0, 0}, up, 1.0f, {2, 0, 0}, up, 1.1f), 0.4f / 1.1f, 1e-6);
    // Back to back is parallel: leaves are two-sided.
    EXPECT_FLOAT_EQ(lodf_collapse_cost(1.0f, {0, 0, 0}, up, 1.0f, {2, 0, 0}, -up, 2.0f), 2.0f);
}

// Two unit squares side by side: the quad on the left one's left edge and the right one's right
// edge covers both, area 2, texture once across it.
TEST(lodf_bake, a_collapse_of_neighbours_side_by_side_keeps_their_area) {
    std::vector<vertex> v;
    const auto add = [&](float x, float z, float u, float w) { v.push_back({{x, 0.0f, z}, {0, 1, 0}, {u, w}}); };
    add(0, 0, 0, 0), add(1, 0, 1, 0), add(1, 1, 1, 1), add(0, 1, 0, 1);  // bl br tr tl
    add(1, 0, 0, 0), add(2, 0, 1, 0), add(2, 1, 1, 1), add(1, 1, 0, 1);
    const auto q = collapse_quad(v, {0, 1, 2, 3}, {4, 5, 6, 7}, 2.0f);
    EXPECT_EQ(q, (std::array<std::uint32_t, 4>{0, 5, 6, 3}));
    // One above the other: bottom edge of the lower, top edge of the upper.
    std::vector<vertex> w = v;
    for (int i = 4; i < 8; ++i) w[i].position = v[i - 4].position + glm::vec3(0, 0, 1);
    EXPECT_EQ(collapse_quad(w, {0, 1, 2, 3}, {4, 5, 6, 7}, 2.0f), (std::array<std::uint32_t, 4>{0, 1, 6, 7}));
}

TEST(lodf_bake, a_generated_tree_bakes_into_a_complete_structure_without_new_vertices) {
    const plant_model plant = generate_plant_model("broadleaf", 3, 64);
    const mesh_data& full = plant.lods[0];
    const std::vector<foliage_leaf> leaves = find_foliage_leaves(full);
    const lodf_model m = bake_lodf(full, plant.has_hierarchy);
    const lodf_structure& f = m.structure;
    ASSERT_GT(f.leaf_count, 1000u);
    EXPECT_EQ(f.leaf_count, leaves.size());
    EXPECT_EQ(f.leaf_count, full.leaves.size()) << "one leaf per generated card";
    const std::uint32_t g = std::uint32_t(f.clusters.size());
    EXPECT_EQ(g, (f.leaf_count + k_lodf_leaves_per_cluster - 1) / k_lodf_leaves_per_cluster);
    EXPECT_EQ(f.collapse_count(), f.leaf_count - g);
    // Eq. 3: every index addresses the full mesh's own vertices.
    EXPECT_EQ(m.vertex_count, full.vertices.size());
    EXPECT_LT(*std::max_element(m.indices.begin(), m.indices.end()), m.vertex_count);
    // Every leaf of F^r has its triangles; a made one is one quad.
    for (const lodf_node& n : f.nodes) {
        ASSERT_GT(n.index_count, 0u);
        if (n.leaf >= f.leaf_count) {
            ASSERT_EQ(n.index_count, 6u);
        }
    }
    // The made quads keep the pairs' area to within a factor of two on average.
    std::printf("mean made-leaf area over the pair's: %.3f\n", m.mean_area_ratio);
    EXPECT_GT(m.mean_area_ratio, 0.5f);
    EXPECT_LT(m.mean_area_ratio, 2.0f);
    // F_0 is exactly the model's foliage: the originals hold every foliage index once.
    std::size_t original_indices = 0, foliage_indices = 0;
    for (const lodf_node& n : f.nodes)
        if (n.leaf < f.leaf_count) original_indices += n.index_count;
    for (const submesh& s : full.submeshes)
        if (s.material == material_kind::leaf) foliage_indices += s.index_count;
    EXPECT_EQ(original_indices, foliage_indices);
    // A cluster's leaves lie back to back in array order: one run of indices per cluster.
    for (const lodf_cluster& c : f.clusters)
        for (std::uint32_t p = 1; p < c.node_count(); ++p)
            ASSERT_EQ(f.nodes[c.first_node + p].first_index,
                      f.nodes[c.first_node + p - 1].first_index + f.nodes[c.first_node + p - 1].index_count);
}

TEST(lodf_bake, the_same_plant_bakes_to_the_same_structure) {
    const plant_model plant = generate_plant_model("conifer", 5, 64);
    const lodf_model a = bake_lodf(plant.lods[0], plant.has_hierarchy);
    const lodf_model b = bake_lodf(plant.lods[0], plant.has_hierarchy);
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(a.structure.changed_group, b.structure.changed_group);
    ASSERT_EQ(a.structure.collapses.size(), b.structure.collapses.size());
    for (std::size_t k = 0; k < a.structure.collapses.size(); ++k)
        ASSERT_EQ(a.structure.collapses[k].old1, b.structure.collapses[k].old1);
}

// Neighbours collapse first: the two leaves of the first tenth of the collapses lie well closer
// together than two leaves of one cluster taken at random.
TEST(lodf_bake, early_collapses_join_near_leaves) {
    const plant_model plant = generate_plant_model("broadleaf", 3, 64);
    const std::vector<foliage_leaf> leaves = find_foliage_leaves(plant.lods[0]);
    const lodf_model m = bake_lodf(plant.lods[0], plant.has_hierarchy);
    const lodf_structure& f = m.structure;
    double early = 0.0, random = 0.0;
    std::size_t n_early = 0, n_random = 0;
    for (std::size_t k = 0; k < f.collapses.size() / 10; ++k) {
        const lodf_collapse& c = f.collapses[k];
        if (c.old1 >= f.leaf_count || c.old2 >= f.leaf_count) continue;
        early += glm::length(leaves[c.old1].centre - leaves[c.old2].centre), ++n_early;
    }
    for (std::uint32_t i = 0; i + 37 < f.leaf_count; i += 37)
        if (f.cluster_of_leaf[i] == f.cluster_of_leaf[i + 37])
            random += glm::length(leaves[i].centre - leaves[i + 37].centre), ++n_random;
    ASSERT_GT(n_early, 50u);
    ASSERT_GT(n_random, 10u);
    std::printf("early collapses join leaves %.3f m apart, random pairs of a cluster %.3f m\n", early / double(n_early),
                random / double(n_random));
    EXPECT_LT(early / double(n_early), 0.5 * random / double(n_random));
}

}  // namespace
}  // namespace sylva
