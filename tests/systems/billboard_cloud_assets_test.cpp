// Scene assets for billboard clouds (Behrendt 2005 §2): loaded only when the LOD policy can
// select them, scaled with the plant, drawn as their own material, with atlas pages of one size
// per texture array (a small plant's 512 x 256 atlas replicated to a tree's 1024 x 512).
#include <gtest/gtest.h>

#include <cmath>

#include "models/image/image_ops.h"
#include "scenarios/scenario_loader.h"
#include "setup/spawn_scenario.h"
#include "tests/tiny_scene.h"

namespace sylva {
namespace {

// A tree (4 m and taller: 1024 x 512 atlas) and a small plant (512 x 256).
scenario tree_and_fern() {
    scenario s = testing::tiny_with_mesh_levels();
    s.species.resize(2);
    s.species[1].name = "fern";
    s.species[1].generator = "fern";
    s.species[1].height_m = 0.8f;
    s.populations.resize(1);
    return s;
}

TEST(billboard_cloud_assets, clouds_are_loaded_only_when_the_policy_can_select_them) {
    const scenario s = tree_and_fern();
    const scene_assets without = build_scene_assets(s, nullptr, {false, false});
    EXPECT_TRUE(without.cloud_albedo.empty());
    EXPECT_EQ(without.library.species[0].triangles_cloud, 0u);

    const scene_assets with = build_scene_assets(s, nullptr, {false, true});
    ASSERT_EQ(with.cloud_albedo.size(), 2u);
    ASSERT_EQ(with.cloud_normal.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(with.cloud_albedo[i].width, 1024u);
        EXPECT_EQ(with.cloud_albedo[i].height, 512u);
        EXPECT_EQ(with.cloud_normal[i].width, 1024u);
        const species_entry& e = with.library.species[i];
        const mesh_data& cloud = with.meshes.at(e.mesh_cloud);
        EXPECT_GT(e.triangles_cloud, 0u);
        EXPECT_EQ(cloud.triangle_count(), e.triangles_cloud);
        EXPECT_EQ(with.library.meshes[e.mesh_cloud].drawn_as, representation::billboard_cloud);
        for (const auto& sub : cloud.submeshes)
            EXPECT_EQ(sub.material, material_kind::billboard_cloud);
    }
    // Scaled with the plant's height_m, as the meshes are (billboard corners may stand out of
    // the plant's own bounds: a cluster's tilted box reaches beyond its leaves).
    scenario taller = s;
    for (auto& sp : taller.species) sp.height_m *= 2.0f;
    const scene_assets doubled = build_scene_assets(taller, nullptr, {false, true});
    for (std::size_t i = 0; i < 2; ++i) {
        const mesh_data& a = with.meshes.at(with.library.species[i].mesh_cloud);
        const mesh_data& b = doubled.meshes.at(doubled.library.species[i].mesh_cloud);
        EXPECT_NEAR(b.bounds_max.y, 2.0f * a.bounds_max.y, 1e-4f * b.bounds_max.y) << i;
        EXPECT_NEAR(b.bounds_min.x, 2.0f * a.bounds_min.x, 1e-4f * std::abs(b.bounds_min.x)) << i;
    }
}

TEST(replicate_upsample, repeats_each_texel_as_a_block) {
    image_rgba8 image{2, 1, {1, 2, 3, 4, 5, 6, 7, 8}};
    const image_rgba8 up = replicate_upsample(image, 2);
    ASSERT_EQ(up.width, 4u);
    ASSERT_EQ(up.height, 2u);
    for (std::uint32_t y = 0; y < 2; ++y) {
        EXPECT_EQ(up.at(0, y)[0], 1);
        EXPECT_EQ(up.at(1, y)[3], 4);
        EXPECT_EQ(up.at(2, y)[0], 5);
        EXPECT_EQ(up.at(3, y)[3], 8);
    }
    EXPECT_EQ(box_downsample(up, 2).texels, image.texels);
    EXPECT_THROW(replicate_upsample(image, 0), std::invalid_argument);
}

}  // namespace
}  // namespace sylva
