// One golden image per representation, each a small scene (160x90, one frame) in which that
// representation covers a good part of the image, so that a regression in its shader path
// moves the image past the tolerance (golden_support.h): crossed billboards; opaque splats;
// soft splats straight into the frame and through the half-size splat layer; lines; billboard
// clouds normal-mapped, pre-lit and SH-lit, and their fades; eco-tile point sets; SH-lit mesh
// levels. Each case first checks that the frame drew that representation, so a golden cannot
// silently guard another one.
//
// Scenes (tests/golden/data/): grove.json, three oaks and three spruces 16 to 27 m away;
// meadow.json, grass tufts a few metres away, whose blades are lines at d' = 1.5 px;
// distant_stand.json, a hundred trees about 170 m away seen through a 15 degree lens, far
// enough to be drawn as their eco tiles' aggregated sets; shell_stand.json, Wang-tiled shrubs
// all drawn by the shells (Behrendt 2005 §3), from above (frame 0) and grazing (frame 1). SYLVA_UPDATE_GOLDEN=1 rewrites the
// goldens (look at each before committing it).
#include <gtest/gtest.h>

#include "../gl/gl_test_support.h"
#include "golden_support.h"
#include "systems/render/splat_layer.h"

namespace sylva {
namespace {

scenario scene(const std::string& file) {
    return load_scenario_file(testing::golden_data(file));
}

constexpr std::uint32_t k_grove_plants = 6;

std::uint32_t drawn(const frame_record& r, representation kind) {
    return r.instances[std::size_t(kind)];
}

std::uint32_t drawn_total(const frame_record& r) {
    std::uint32_t total = 0;
    for (const std::uint32_t n : r.instances) total += n;
    return total;
}

// Every plant as `kind`, lit as `lighting` ("": as the scenario says).
player_options every_plant_as(representation kind, std::string lighting = "") {
    player_options options;
    options.scenario_lod = false;
    options.policy = {lod_policy::kind::single, kind, kind, 0.0f};
    options.lighting = std::move(lighting);
    return options;
}

// Deussen 2002's points and lines at d' = `sample_distance_px`, c_p = 1.3, with the paper's
// primitive costs (the same selection on every machine).
player_options points_and_lines(float sample_distance_px, splat_style splats) {
    player_options options;
    options.scenario_lod = false;
    options.measure_costs = false;
    options.policy.mode = lod_policy::kind::points_lines;
    options.policy.points = {sample_distance_px, 1.3f, true, splats, true};
    return options;
}

void expect_lit(const testing::rendered_frame& frame, lighting_variant lighting) {
    ASSERT_FALSE(frame.species_lighting.empty());
    for (const lighting_variant l : frame.species_lighting) EXPECT_EQ(l, lighting);
}

TEST(representation_golden, crossed_billboards) {
    SYLVA_REQUIRE_GL();
    const auto frame = testing::render_frame(scene("grove.json"), 0,
                                             every_plant_as(representation::crossed_billboard));
    EXPECT_EQ(drawn(frame.record, representation::crossed_billboard), k_grove_plants);
    EXPECT_EQ(drawn_total(frame.record), k_grove_plants);
    EXPECT_EQ(frame.record.triangles, 4u * k_grove_plants);  // two crossed quads each
    testing::expect_matches_golden(frame.image, "grove_crossed_billboards.png");
}

TEST(representation_golden, opaque_splats) {
    SYLVA_REQUIRE_GL();
    const auto frame =
        testing::render_frame(scene("grove.json"), 0, points_and_lines(2.0f, splat_style::opaque));
    EXPECT_EQ(drawn(frame.record, representation::points), k_grove_plants);
    EXPECT_EQ(frame.record.triangles, 0u);
    EXPECT_GT(frame.record.points, 50 * frame.record.lines);  // the crowns' leaves, not needles
    testing::expect_matches_golden(frame.image, "grove_opaque_splats.png");
}

// Soft splats of d' = 1 (2.3 px) are blended straight into the frame.
TEST(representation_golden, soft_splats_in_the_frame) {
    SYLVA_REQUIRE_GL();
    const player_options options = points_and_lines(1.0f, splat_style::soft);
    ASSERT_LT(soft_splat_size_px(options.policy.points), k_splat_layer_min_side_px);
    const auto frame = testing::render_frame(scene("grove.json"), 0, options);
    EXPECT_EQ(drawn(frame.record, representation::points), k_grove_plants);
    EXPECT_GT(frame.record.points, 10 * frame.record.triangles);
    testing::expect_matches_golden(frame.image, "grove_soft_splats_d1.png");
}

// Soft splats of d' = 2 (4.6 px) go through the half-size splat layer. Seen from above, so the
// crowns' edges lie over the terrain, where the layer's composite depth (the nearest of the 2x2
// texels it filters) decides what shows: from the grove's own eye height, taking one texel's
// depth instead moved 0.10 % of the pixels, under the tolerance; from above, 0.36 %.
TEST(representation_golden, soft_splats_in_the_splat_layer) {
    SYLVA_REQUIRE_GL();
    scenario s = scene("grove.json");
    s.camera.keyframes.at(0).key.position.y = 10.0;  // metres above the terrain
    s.camera.keyframes.at(0).key.target.y = 3.0;
    const player_options options = points_and_lines(2.0f, splat_style::soft);
    ASSERT_GE(soft_splat_size_px(options.policy.points), k_splat_layer_min_side_px);
    const auto frame = testing::render_frame(s, 0, options);
    EXPECT_EQ(drawn(frame.record, representation::points), k_grove_plants);
    EXPECT_EQ(frame.record.triangles, 0u);
    EXPECT_GT(frame.record.points, 50 * frame.record.lines);
    testing::expect_matches_golden(frame.image, "grove_soft_splats_d2.png");
}

// Grass blades at d' = 1.5 px: wide lines (line.geom), most parts lines rather than splats.
TEST(representation_golden, lines) {
    SYLVA_REQUIRE_GL();
    const auto frame =
        testing::render_frame(scene("meadow.json"), 0, points_and_lines(1.5f, splat_style::opaque));
    EXPECT_GT(drawn(frame.record, representation::points), 0u);
    EXPECT_EQ(frame.record.triangles, 0u);
    EXPECT_GT(frame.record.lines, 3 * frame.record.points);
    testing::expect_matches_golden(frame.image, "meadow_lines.png");
}

// Every grove plant as its billboard cloud, lit one way: only clouds are drawn, and every
// species is lit as asked.
void expect_cloud_golden(const char* lighting, lighting_variant variant, const char* golden) {
    const auto frame = testing::render_frame(scene("grove.json"), 0,
                                             every_plant_as(representation::billboard_cloud, lighting));
    EXPECT_EQ(drawn(frame.record, representation::billboard_cloud), k_grove_plants);
    EXPECT_EQ(drawn_total(frame.record), k_grove_plants);
    expect_lit(frame, variant);
    testing::expect_matches_golden(frame.image, golden);
}

TEST(representation_golden, billboard_clouds_normal_mapped) {
    SYLVA_REQUIRE_GL();
    expect_cloud_golden("normal_mapped", lighting_variant::normal_mapped, "grove_clouds_normal_mapped.png");
}

TEST(representation_golden, billboard_clouds_pre_lit) {
    SYLVA_REQUIRE_GL();
    expect_cloud_golden("pre_lit", lighting_variant::pre_lit, "grove_clouds_pre_lit.png");
}

TEST(representation_golden, billboard_clouds_sh) {
    SYLVA_REQUIRE_GL();
    expect_cloud_golden("sh", lighting_variant::sh, "grove_clouds_sh.png");
}

// Behrendt 2005 §2.3's sort-free fades, as the bench's billboard_clouds configuration draws
// them: with the cloud distance at 25 m, the nearest plant is a mesh, the farthest a cloud and
// the four between in the first half of the band, each a whole mesh with its cloud fading in
// under the modified alpha test (cloud.frag cloud_alpha_threshold).
TEST(representation_golden, billboard_cloud_fades) {
    SYLVA_REQUIRE_GL();
    player_options options;
    options.scenario_lod = false;
    options.policy.mode = lod_policy::kind::billboard_clouds;
    options.policy.cloud_distance_m = 25.0f;
    const auto frame = testing::render_frame(scene("grove.json"), 0, options);
    const std::uint32_t meshes = drawn(frame.record, representation::mesh_full);
    const std::uint32_t clouds = drawn(frame.record, representation::billboard_cloud);
    EXPECT_GE(meshes, 1u);
    EXPECT_GE(clouds, 1u);
    EXPECT_GE(meshes + clouds, k_grove_plants + 3);  // at least three plants drawn both ways
    EXPECT_EQ(drawn_total(frame.record), meshes + clouds);
    testing::expect_matches_golden(frame.image, "grove_cloud_fades.png");
}

// Deussen 2002 §6.2: every plant of the distant stand drawn through its eco tile's set. Opaque
// splats: soft ones smooth a tile-set regression away (measured: reading the next species'
// texture layer moved 0.13 % of the pixels by more than 16 with soft splats, 4.8 % with opaque).
TEST(representation_golden, eco_tile_point_sets) {
    SYLVA_REQUIRE_GL();
    const auto frame = testing::render_frame(scene("distant_stand.json"), 0,
                                             points_and_lines(2.0f, splat_style::opaque));
    EXPECT_GT(frame.record.aggregated_tiles, 1u);
    EXPECT_EQ(frame.record.aggregated_plants, frame.plants);
    // No plant on its own: every seen plant is on the eco-tile rung.
    EXPECT_GT(drawn(frame.record, representation::eco_tile), 0u);
    EXPECT_EQ(drawn_total(frame.record), drawn(frame.record, representation::eco_tile));
    EXPECT_GT(frame.record.points, 1000u);
    testing::expect_matches_golden(frame.image, "distant_stand_tile_sets.png");
}

// The grove's mesh levels lit by SH transfer (Behrendt 2005 §4); switch distances x 0.6 put
// the nearer plants at full detail and the farther ones at reduced detail.
TEST(representation_golden, sh_mesh_levels) {
    SYLVA_REQUIRE_GL();
    scenario s = scene("grove.json");
    s.camera.lod_scale = 0.6f;
    player_options options;
    options.lighting = "sh";
    const auto frame = testing::render_frame(s, 0, options);
    EXPECT_GT(drawn(frame.record, representation::mesh_full), 0u);
    EXPECT_GT(drawn(frame.record, representation::mesh_reduced), 0u);
    EXPECT_EQ(drawn_total(frame.record), k_grove_plants);
    expect_lit(frame, lighting_variant::sh);
    testing::expect_matches_golden(frame.image, "grove_sh_mesh_levels.png");
}

// Behrendt 2005 §3: the shells from above, where every slice lies over the one below, and at a
// grazing angle (4 m up, 62 m away), where the slanted slices stand toward the viewer. Every
// plant is on the shell rung, so the frame is terrain and shells only.
TEST(representation_golden, shells_from_above_and_grazing) {
    SYLVA_REQUIRE_GL();
    for (const std::uint64_t frame : {0u, 1u}) {
        const auto f = testing::render_frame(scene("shell_stand.json"), frame);
        EXPECT_GT(drawn(f.record, representation::shell), 100u);
        EXPECT_EQ(drawn_total(f.record), drawn(f.record, representation::shell));
        EXPECT_EQ(f.record.triangles, 0u);
        testing::expect_matches_golden(f.image, frame == 0 ? "shells_from_above.png" : "shells_grazing.png");
    }
}

}  // namespace
}  // namespace sylva
