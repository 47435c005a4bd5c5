// The paper's traversal (lod/lodf_traversal.h, Rebollo 2006 §5) on a baked plant: both updates
// draw the same triangles at every level, and the bytes each uploads are what it changed.
#include "lod/lodf_traversal.h"

#include <gtest/gtest.h>

#include "models/generate/plant_library.h"

namespace sylva {
namespace {

TEST(lodf_traversal, levels_go_down_uniformly_and_back_to_f0) {
    lodf_structure f;
    f.leaf_count = 101;
    f.changed_group.assign(100, 0);
    EXPECT_EQ(traversal_levels(f, 4), (std::vector<std::uint32_t>{25, 50, 75, 100, 75, 50, 25, 0}));
}

TEST(lodf_traversal, both_updates_draw_the_same_and_lodf_uploads_a_command_per_changed_cluster) {
    const plant_model plant = generate_plant_model("broadleaf", 3, 64);
    const lodf_model m = bake_lodf(plant.lods[0], plant.has_hierarchy);
    const std::vector<std::uint32_t> levels = traversal_levels(m.structure, 20);
    const std::vector<traversal_change> changes = traverse_lodf(m, levels, true);  // throws on a mismatch
    ASSERT_EQ(changes.size(), levels.size());
    const auto g = std::uint32_t(m.structure.clusters.size());
    for (const traversal_change& c : changes) {
        EXPECT_GT(c.clusters_changed, 0u);
        EXPECT_LE(c.clusters_changed, g);
        EXPECT_EQ(c.lodf_bytes, 20u * c.clusters_changed);
        EXPECT_GT(c.whole_bytes, 0u);
        // Every leaf drawn is at least one triangle of 12 index bytes.
        EXPECT_GE(c.whole_bytes, 12u * c.leaves);
    }
    EXPECT_EQ(changes.back().leaves, m.structure.leaf_count);
    EXPECT_EQ(changes[levels.size() / 2 - 1].leaves, g) << "the coarsest level: one leaf per cluster";
}

}  // namespace
}  // namespace sylva
