#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "models/cache/bake_cache.h"
#include "scenarios/scenario_loader.h"
#include "setup/spawn_scenario.h"
#include "setup/species_models.h"
#include "tests/tiny_scene.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

scenario tiny() {
    return testing::tiny_with_mesh_levels();
}

TEST(crossed_billboard_assets, every_species_gets_a_billboard_mesh_and_equal_sized_atlas_layers) {
    const scenario s = tiny();
    const fs::path root = fs::temp_directory_path() / ("sylva_billboard_assets_" + std::to_string(::getpid()));
    fs::remove_all(root);
    bake_cache cache(root);
    const scene_assets assets = build_scene_assets(s, &cache);

    ASSERT_EQ(assets.library.species.size(), s.species.size());
    ASSERT_EQ(assets.billboard_albedo.size(), assets.leaf_textures.size());
    ASSERT_EQ(assets.billboard_normal.size(), assets.leaf_textures.size());
    for (std::size_t i = 0; i < assets.library.species.size(); ++i) {
        const species_entry& e = assets.library.species[i];
        ASSERT_LT(e.mesh_billboard, assets.meshes.size());
        EXPECT_NE(e.mesh_billboard, e.mesh_far);
        const mesh_data& quads = assets.meshes[e.mesh_billboard];
        EXPECT_EQ(e.triangles_billboard, 4u);
        EXPECT_EQ(quads.triangle_count(), 4u);
        ASSERT_EQ(quads.submeshes.size(), 1u);
        EXPECT_EQ(quads.submeshes[0].material, material_kind::billboard);
        EXPECT_EQ(assets.library.meshes[e.mesh_billboard].drawn_as, representation::crossed_billboard);
        EXPECT_EQ(assets.library.meshes[e.mesh_billboard].triangles, 4u);
        // Scaled with the plant: as tall as its full mesh (the scenario's height_m).
        const mesh_data& full = assets.meshes[e.mesh_full];
        EXPECT_NEAR(quads.bounds_max.y, full.bounds_max.y, 1e-3f * full.bounds_max.y) << e.name;
        EXPECT_NEAR(quads.bounds_max.y, s.species[i].height_m, 1e-3f * s.species[i].height_m) << e.name;

        const image_rgba8& albedo = assets.billboard_albedo[i];
        EXPECT_EQ(albedo.width,
                  7 * k_species_billboard_resolution);  // two quads, eight facing views
        EXPECT_EQ(albedo.height, k_species_billboard_resolution);
        EXPECT_EQ(albedo.texels.size(), std::size_t(albedo.width) * albedo.height * 4);
        EXPECT_EQ(assets.billboard_normal[i].width, albedo.width);
        EXPECT_EQ(assets.billboard_normal[i].height, albedo.height);
        std::size_t covered = 0;
        for (std::size_t t = 3; t < albedo.texels.size(); t += 4) covered += albedo.texels[t] > 0;
        EXPECT_GT(covered, albedo.texels.size() / 4 / 20) << e.name;  // > 5 % of the atlas
    }

    // A second build reads every billboard from the cache, byte for byte.
    bake_cache again(root);
    const scene_assets cached = build_scene_assets(s, &again);
    EXPECT_EQ(again.misses(), 0u);
    EXPECT_EQ(again.hits(), 2 * s.species.size());  // plant model and billboard per species
    for (std::size_t i = 0; i < assets.billboard_albedo.size(); ++i) {
        EXPECT_EQ(cached.billboard_albedo[i].texels, assets.billboard_albedo[i].texels);
        EXPECT_EQ(cached.billboard_normal[i].texels, assets.billboard_normal[i].texels);
    }
    EXPECT_TRUE(fs::exists(again.path_of("billboards", species_billboard_key(s.species[0], species_seed_of(s.seed, 0)))));
    fs::remove_all(root);
}

TEST(crossed_billboard_assets, the_billboard_key_changes_with_the_species_and_not_with_its_height) {
    species_settings oak;
    oak.generator = "broadleaf";
    species_settings tall_oak = oak;
    tall_oak.height_m = 30.0f;
    species_settings spruce = oak;
    spruce.generator = "conifer";
    EXPECT_EQ(species_billboard_key(oak, 1), species_billboard_key(tall_oak, 1));
    EXPECT_NE(species_billboard_key(oak, 1), species_billboard_key(oak, 2));
    EXPECT_NE(species_billboard_key(oak, 1), species_billboard_key(spruce, 1));
    EXPECT_NE(species_billboard_key(oak, 1), species_model_key(oak, 1));
}

}  // namespace
}  // namespace sylva
