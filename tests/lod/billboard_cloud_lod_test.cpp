// Behrendt 2005 §2.3 as pure functions: the representation bands of the billboard-cloud policy
// and the distance-threshold fade, checked on hand-computed values at band edges and inside;
// and the threshold against a real bake (fully shown keeps every covered texel, gone keeps none).
#include "lod/billboard_cloud_lod.h"

#include <gtest/gtest.h>

#include "expect_choice.h"

#include <cmath>

#include "models/bake/billboard_cloud.h"
#include "models/generate/plant_library.h"

namespace sylva {
namespace {

species_entry oak() {
    species_entry s;
    s.reduced_distance_m = 50.0f;
    s.far_distance_m = 200.0f;
    return s;
}

using testing::expect_choice;

TEST(billboard_cloud_lod, polygons_near_the_cloud_from_30_m_crossed_billboards_beyond_the_far_distance) {
    const species_entry s = oak();
    // Cloud band 30 m ± 15 %: 25.5 .. 34.5 m; far band 200 m ± 15 %: 170 .. 230 m.
    expect_choice(choose_cloud_lod(s, 30.0f, 10.0f, 1.0f, 1.0f), representation::mesh_full, representation::none, 0.0f);
    expect_choice(choose_cloud_lod(s, 30.0f, 25.4f, 1.0f, 1.0f), representation::mesh_full, representation::none, 0.0f);
    expect_choice(choose_cloud_lod(s, 30.0f, 100.0f, 1.0f, 1.0f), representation::billboard_cloud,
                  representation::none, 0.0f);
    expect_choice(choose_cloud_lod(s, 30.0f, 34.6f, 1.0f, 1.0f), representation::billboard_cloud,
                  representation::none, 0.0f);
    expect_choice(choose_cloud_lod(s, 30.0f, 169.9f, 1.0f, 1.0f), representation::billboard_cloud,
                  representation::none, 0.0f);
    expect_choice(choose_cloud_lod(s, 30.0f, 230.1f, 1.0f, 1.0f), representation::crossed_billboard,
                  representation::none, 0.0f);
    expect_choice(choose_cloud_lod(s, 30.0f, std::nanf(""), 1.0f, 1.0f), representation::crossed_billboard,
                  representation::none, 0.0f);
}

TEST(billboard_cloud_lod, across_a_band_the_farther_fades_in_then_the_nearer_fades_out) {
    const species_entry s = oak();
    // t = (d - 25.5) / 9 across the cloud band; the cloud rises 0 -> 1 over t < 1/2, then is the
    // primary and the mesh falls 1 -> 0.
    expect_choice(choose_cloud_lod(s, 30.0f, 25.6f, 1.0f, 1.0f), representation::mesh_full,
                  representation::billboard_cloud, 2.0f * 0.1f / 9.0f);
    expect_choice(choose_cloud_lod(s, 30.0f, 27.75f, 1.0f, 1.0f), representation::mesh_full,
                  representation::billboard_cloud, 0.5f);
    expect_choice(choose_cloud_lod(s, 30.0f, 30.0f, 1.0f, 1.0f), representation::billboard_cloud,
                  representation::mesh_full, 1.0f);
    expect_choice(choose_cloud_lod(s, 30.0f, 33.0f, 1.0f, 1.0f), representation::billboard_cloud,
                  representation::mesh_full, 1.0f / 3.0f);
    expect_choice(choose_cloud_lod(s, 30.0f, 34.4f, 1.0f, 1.0f), representation::billboard_cloud,
                  representation::mesh_full, 2.0f * 0.1f / 9.0f);
    // Far band, t = (d - 170) / 60: the crossed billboard fades in, then the cloud fades out.
    expect_choice(choose_cloud_lod(s, 30.0f, 176.0f, 1.0f, 1.0f), representation::billboard_cloud,
                  representation::crossed_billboard, 0.2f);
    expect_choice(choose_cloud_lod(s, 30.0f, 215.0f, 1.0f, 1.0f), representation::crossed_billboard,
                  representation::billboard_cloud, 0.5f);
}

TEST(billboard_cloud_lod, distances_scale_with_plant_size_and_lod_scale_and_the_near_mesh_follows_the_levels) {
    const species_entry s = oak();
    // Scale 2: the cloud band is 51 .. 69 m; 55.5 m is a quarter in.
    expect_choice(choose_cloud_lod(s, 30.0f, 55.5f, 2.0f, 1.0f), representation::mesh_full,
                  representation::billboard_cloud, 0.5f);
    expect_choice(choose_cloud_lod(s, 30.0f, 55.5f, 2.0f, 0.5f), representation::billboard_cloud,
                  representation::none, 0.0f);
    // A species reduced from 20 m: the band hands over between the reduced mesh and the cloud.
    species_entry shrub = oak();
    shrub.reduced_distance_m = 20.0f;
    expect_choice(choose_cloud_lod(shrub, 30.0f, 27.75f, 1.0f, 1.0f), representation::mesh_reduced,
                  representation::billboard_cloud, 0.5f);
    expect_choice(choose_cloud_lod(shrub, 30.0f, 15.0f, 1.0f, 1.0f), representation::mesh_full,
                  representation::none, 0.0f);
}

TEST(billboard_cloud_lod, a_short_far_distance_pulls_the_cloud_band_in_so_bands_never_overlap) {
    species_entry hazel = oak();
    hazel.far_distance_m = 30.0f;
    // 30 x 0.85 / 1.15: the cloud band ends where the far band starts (25.5 m).
    EXPECT_NEAR(cloud_switch_distance(hazel, 30.0f), 30.0f * 0.85f / 1.15f, 1e-4f);
    EXPECT_NEAR(cloud_switch_distance(hazel, 30.0f) * 1.15f, 25.5f, 1e-4f);
    EXPECT_EQ(cloud_switch_distance(oak(), 30.0f), 30.0f);
    expect_choice(choose_cloud_lod(hazel, 30.0f, 25.6f, 1.0f, 1.0f), representation::billboard_cloud,
                  representation::crossed_billboard, 2.0f * 0.1f / 9.0f);
}

TEST(billboard_cloud_lod, the_alpha_threshold_is_piecewise_linear_in_the_fade_from_shown_to_gone) {
    // Knots (fade, threshold): (1, 0.18), (3/4, 0.75), (1/2, 0.90), (0, 1.02); halfway between.
    EXPECT_FLOAT_EQ(cloud_alpha_threshold(1.0f), 0.18f);
    EXPECT_FLOAT_EQ(cloud_alpha_threshold(0.875f), 0.465f);
    EXPECT_FLOAT_EQ(cloud_alpha_threshold(0.75f), 0.75f);
    EXPECT_FLOAT_EQ(cloud_alpha_threshold(0.625f), 0.825f);
    EXPECT_FLOAT_EQ(cloud_alpha_threshold(0.5f), 0.90f);
    EXPECT_FLOAT_EQ(cloud_alpha_threshold(0.25f), 0.96f);
    EXPECT_FLOAT_EQ(cloud_alpha_threshold(0.0f), 1.02f);
    EXPECT_FLOAT_EQ(cloud_alpha_threshold(2.0f), 0.18f);
    EXPECT_FLOAT_EQ(cloud_alpha_threshold(-1.0f), 1.02f);
    for (float f = 0.0f; f < 1.0f; f += 0.01f) EXPECT_GE(cloud_alpha_threshold(f), cloud_alpha_threshold(f + 0.01f));
}

// The bake's colour alpha is coverage x gaussian: every texel the coverage test keeps
// (normal-page alpha >= 0.5) must pass the fully-shown threshold, or a cloud drawn whole would
// lose its billboards' corners; and nothing may pass the threshold of a cloud that is gone.
TEST(billboard_cloud_lod, fully_shown_keeps_every_covered_texel_of_a_bake_and_gone_keeps_none) {
    const plant_model model = generate_plant_model("grass", 7, 64);
    const billboard_cloud cloud = bake_billboard_cloud(model, default_billboard_cloud_settings(model));
    const image_rgba8& albedo = cloud.page(cloud_atlas_page::albedo);
    const image_rgba8& normal = cloud.page(cloud_atlas_page::normal);
    std::size_t covered = 0, kept = 0, kept_when_gone = 0, kept_at_half = 0;
    for (std::size_t i = 3; i < albedo.texels.size(); i += 4) {
        const float a = float(albedo.texels[i]) / 255.0f;
        if (float(normal.texels[i]) / 255.0f < 0.5f) continue;
        ++covered;
        kept += a >= cloud_alpha_threshold(1.0f);
        kept_at_half += a >= cloud_alpha_threshold(0.5f);
        kept_when_gone += a >= cloud_alpha_threshold(0.0f);
    }
    ASSERT_GT(covered, 1000u);
    EXPECT_EQ(kept, covered);
    EXPECT_EQ(kept_when_gone, 0u);
    EXPECT_GT(kept_at_half, 0u);  // halfway, billboards have shrunk toward their centres
    EXPECT_LT(kept_at_half, covered);
}

}  // namespace
}  // namespace sylva
