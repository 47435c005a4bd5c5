// The rival of LoDF at equal leaf count (lod/leaf_shrink.h): N leaves of a fixed random order,
// enlarged so the foliage keeps its area.
#include "lod/leaf_shrink.h"

#include <gtest/gtest.h>

#include "models/bake/lodf_leaves.h"
#include "models/generate/plant_library.h"

namespace sylva {
namespace {

double foliage_area(const mesh_data& m) {
    double area = 0.0;
    for (const foliage_leaf& l : find_foliage_leaves(m)) area += l.area;
    return area;
}

TEST(leaf_shrink, keeps_n_leaves_and_the_foliage_area) {
    const plant_model plant = generate_plant_model("broadleaf", 3, 32);
    const mesh_data& full = plant.lods[0];
    const std::size_t total = find_foliage_leaves(full).size();
    const mesh_data quarter = leaf_shrink_mesh(full, std::uint32_t(total / 4), 7);
    EXPECT_EQ(find_foliage_leaves(quarter).size(), total / 4);
    // Each survivor is scaled by √(L / N) about its centre: area × L / N, total area kept.
    EXPECT_NEAR(foliage_area(quarter), foliage_area(full), 0.02 * foliage_area(full));
    // The bark is untouched; every leaf at N = 0 (or more than there are).
    EXPECT_EQ(leaf_shrink_mesh(full, 0, 7).indices.size(), full.indices.size());
    // A fixed order: the same seed keeps the same leaves, another seed others.
    EXPECT_EQ(leaf_shrink_mesh(full, 100, 7).indices, leaf_shrink_mesh(full, 100, 7).indices);
    EXPECT_NE(leaf_shrink_mesh(full, 100, 7).indices, leaf_shrink_mesh(full, 100, 8).indices);
}

}  // namespace
}  // namespace sylva
