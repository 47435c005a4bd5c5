// Stress: eco tiles (Deussen 2002 §6.2) over degenerate plant layouts, all at one point or on a
// line, terminate with bounded depth, hold every plant in exactly one leaf and cull exactly as
// flat culling does.
#include <gtest/gtest.h>

#include <vector>

#include "app/stress/stress_checks.h"
#include "stress_support.h"
#include "lod/eco_tiles.h"

namespace sylva {
namespace {

TEST(plant_cluster_stress, points_and_lines_give_bounded_trees_that_cull_like_flat) {
    const auto rows = check_plant_clusters(2);
    ASSERT_EQ(rows.size(), 5u);
    testing::expect_all_pass(rows);
    for (const stress_row& r : rows) EXPECT_EQ(r.value, 0.0) << r.check;  // cull differences
}

TEST(plant_cluster_stress, coincident_plants_split_one_quadrant_per_level_to_the_depth_cap) {
    // 100 plants at one point, 10 per tile: every level splits into four, of which one holds
    // all plants, down to the cap: 4 x 24 + 1 nodes, 3 x 24 + 1 leaves, one with all 100.
    const std::vector<glm::dvec2> same(100, glm::dvec2(1.0, 2.0));
    const eco_tile_tree tree = build_eco_tiles(same, {0.0, 0.0, 8.0, 8.0}, 10);
    EXPECT_EQ(tree.nodes.size(), 4u * k_max_eco_tile_depth + 1u);
    std::size_t leaves = 0, full_leaves = 0;
    for (const eco_tile_node& n : tree.nodes) {
        if (!n.is_leaf()) continue;
        ++leaves;
        full_leaves += n.plant_count == 100 ? 1 : 0;
        if (n.plant_count == 100) {
            EXPECT_EQ(n.depth, k_max_eco_tile_depth);
        }
    }
    EXPECT_EQ(leaves, 3u * k_max_eco_tile_depth + 1u);
    EXPECT_EQ(full_leaves, 1u);
}

TEST(plant_cluster_stress, plants_on_a_split_line_go_to_the_plus_side_and_stay_in_their_leaf) {
    // 8 plants on x = 4, the root's split line: all go to the +x quadrants (eco_tiles.h).
    std::vector<glm::dvec2> line;
    for (int i = 0; i < 8; ++i) line.emplace_back(4.0, 0.5 + i);
    const eco_tile_tree tree = build_eco_tiles(line, {0.0, 0.0, 8.0, 8.0}, 4);
    ASSERT_FALSE(tree.nodes[0].is_leaf());
    EXPECT_EQ(tree.nodes[tree.nodes[0].children[0]].plant_count, 0u);  // -x -z
    EXPECT_EQ(tree.nodes[tree.nodes[0].children[1]].plant_count, 4u);  // +x -z
    EXPECT_EQ(tree.nodes[tree.nodes[0].children[2]].plant_count, 0u);  // -x +z
    EXPECT_EQ(tree.nodes[tree.nodes[0].children[3]].plant_count, 4u);  // +x +z
}

}  // namespace
}  // namespace sylva
