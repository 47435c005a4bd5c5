// The representation ladder (DESIGN §1.5, lod/ladder.h) as pure functions: the rung and its
// partner at hand-computed projected sizes, the projected size itself, and the rules every
// ladder must keep.
#include "lod/ladder.h"

#include <gtest/gtest.h>

#include "expect_choice.h"

#include <cmath>

namespace sylva {
namespace {

// mesh_full | 200 px ± 10 % | billboard_cloud | 50 px ± 20 % | crossed_billboard
ladder three_rungs() {
    ladder l;
    l.count = 3;
    l.rungs = {representation::mesh_full, representation::billboard_cloud, representation::crossed_billboard};
    l.below_px = {0.0f, 200.0f, 50.0f};
    l.band = {0.0f, 0.1f, 0.2f};
    return l;
}

using testing::expect_choice;

TEST(ladder, each_rung_holds_between_its_bands) {
    const ladder l = three_rungs();
    // Band 1: 180 .. 220 px; band 2: 40 .. 60 px (edges just outside: 200 x 1.1f is not 220).
    expect_choice(choose_rung(l, 1000.0f), representation::mesh_full, representation::none, 0.0f);
    expect_choice(choose_rung(l, 220.01f), representation::mesh_full, representation::none, 0.0f);
    expect_choice(choose_rung(l, 180.0f), representation::billboard_cloud, representation::none, 0.0f);
    expect_choice(choose_rung(l, 100.0f), representation::billboard_cloud, representation::none, 0.0f);
    expect_choice(choose_rung(l, 60.01f), representation::billboard_cloud, representation::none, 0.0f);
    expect_choice(choose_rung(l, 40.0f), representation::crossed_billboard, representation::none, 0.0f);
    expect_choice(choose_rung(l, 0.5f), representation::crossed_billboard, representation::none, 0.0f);
    expect_choice(choose_rung(l, 0.0f), representation::crossed_billboard, representation::none, 0.0f);
    expect_choice(choose_rung(l, std::nanf("")), representation::crossed_billboard, representation::none, 0.0f);
    expect_choice(choose_rung(l, INFINITY), representation::mesh_full, representation::none, 0.0f);
}

TEST(ladder, across_a_band_the_farther_rung_fades_in_then_the_nearer_fades_out) {
    const ladder l = three_rungs();
    // Band 1, t = (220 - size) / 40: the cloud rises 0 -> 1 over t < 1/2 (220 .. 200 px), then
    // is the primary and the mesh falls 1 -> 0 (200 .. 180 px).
    expect_choice(choose_rung(l, 219.0f), representation::mesh_full, representation::billboard_cloud, 2.0f / 40.0f);
    expect_choice(choose_rung(l, 210.0f), representation::mesh_full, representation::billboard_cloud, 0.5f);
    expect_choice(choose_rung(l, 200.0f), representation::billboard_cloud, representation::mesh_full, 1.0f);
    expect_choice(choose_rung(l, 190.0f), representation::billboard_cloud, representation::mesh_full, 0.5f);
    expect_choice(choose_rung(l, 181.0f), representation::billboard_cloud, representation::mesh_full, 2.0f / 40.0f);
    // Band 2, t = (60 - size) / 20.
    expect_choice(choose_rung(l, 55.0f), representation::billboard_cloud, representation::crossed_billboard, 0.5f);
    expect_choice(choose_rung(l, 45.0f), representation::crossed_billboard, representation::billboard_cloud, 0.5f);
}

TEST(ladder, a_zero_band_is_a_hard_switch_and_one_rung_is_every_size) {
    ladder l = three_rungs();
    l.band[1] = 0.0f;
    expect_choice(choose_rung(l, 200.0f), representation::mesh_full, representation::none, 0.0f);
    expect_choice(choose_rung(l, 199.99f), representation::billboard_cloud, representation::none, 0.0f);
    ladder one;
    one.count = 1;
    one.rungs[0] = representation::points;
    expect_choice(choose_rung(one, 1e6f), representation::points, representation::none, 0.0f);
    expect_choice(choose_rung(one, 1e-6f), representation::points, representation::none, 0.0f);
    expect_choice(choose_rung(ladder{}, 10.0f), representation::none, representation::none, 0.0f);
}

// Behrendt 2005 §3.3 end: the step into a shell rung follows the shell's fade by distance, the
// rest of the ladder the plant's size. three_rungs with a shell after the crossed billboard.
TEST(ladder, the_step_into_the_shell_follows_the_shells_fade_not_the_size) {
    ladder l = three_rungs();
    l.count = 4;
    l.rungs[3] = representation::shell;
    l.below_px[3] = 10.0f;
    l.band[3] = 0.5f;
    // Shell fade below 1/2: what the rest chooses by size, whatever the shell rung's own size.
    expect_choice(choose_rung_with_shell(l, 5.0f, 0.0f), representation::crossed_billboard, representation::none, 0.0f);
    expect_choice(choose_rung_with_shell(l, 210.0f, 0.4f), representation::mesh_full, representation::billboard_cloud,
                  0.5f);
    // From 1/2 the shell is primary, the nearer rung fading out as 2 (1 - fade): 0.7 -> 0.6.
    expect_choice(choose_rung_with_shell(l, 45.0f, 0.7f), representation::shell, representation::crossed_billboard,
                  0.6f);
    expect_choice(choose_rung_with_shell(l, 45.0f, 0.5f), representation::shell, representation::crossed_billboard,
                  1.0f);
    expect_choice(choose_rung_with_shell(l, 500.0f, 1.0f), representation::shell, representation::none, 0.0f);
    // A ladder without a shell rung: choose_rung.
    expect_choice(choose_rung_with_shell(three_rungs(), 45.0f, 1.0f), representation::crossed_billboard,
                  representation::billboard_cloud, 0.5f);
}

TEST(ladder, projected_size_is_the_diameter_over_a_pixel_on_the_image_plane) {
    // fov 90°: the image plane at distance 1 is 2 units high; at 500 px a pixel is 1/250 of a
    // unit. A 5 m radius at 50 m spans 10 / 50 = 0.2 units: 50 px.
    EXPECT_NEAR(projected_size_px(5.0f, 50.0f, float(M_PI / 2.0), 500.0f), 50.0f, 1e-3f);
    // fov 60°: 2·tan(30°) = 1.1547 units over 270 px; a 7 m radius at 30 m is 0.4667 units.
    EXPECT_NEAR(projected_size_px(7.0f, 30.0f, float(M_PI / 3.0), 270.0f), 0.46667f / (1.1547005f / 270.0f), 1e-2f);
    // Twice the resolution, twice the pixels: a ladder means the same at any resolution.
    EXPECT_NEAR(projected_size_px(7.0f, 30.0f, 1.0f, 540.0f), 2.0f * projected_size_px(7.0f, 30.0f, 1.0f, 270.0f),
                1e-3f);
}

TEST(ladder, rung_names_round_trip_and_points_lines_is_the_points_representation) {
    for (const std::string_view name : k_rung_names) EXPECT_EQ(rung_name(*rung_of_name(name)), name);
    EXPECT_EQ(rung_of_name("points_lines"), representation::points);
    EXPECT_FALSE(rung_of_name("points"));
    EXPECT_FALSE(rung_of_name("none"));
    EXPECT_EQ(rung_name(representation::none), "");
}

TEST(ladder, a_facing_billboard_casts_as_its_crossed_billboard_unless_its_ladder_names_a_caster) {
    ladder l;
    l.count = 2;
    l.rungs = {representation::crossed_billboard, representation::facing_billboard};
    l.below_px = {0.0f, 20.0f};
    l.band = {0.0f, 0.15f};
    EXPECT_FALSE(find_ladder_problem(l));
    EXPECT_EQ(rung_of_name("facing_billboard"), representation::facing_billboard);
    EXPECT_EQ(l.caster_of(representation::facing_billboard), representation::crossed_billboard);
    EXPECT_EQ(l.caster_of(representation::crossed_billboard), representation::crossed_billboard);
    EXPECT_TRUE(casts_as_a_mesh(representation::facing_billboard));
    l.shadow[1] = representation::facing_billboard;
    EXPECT_EQ(l.caster_of(representation::facing_billboard), representation::facing_billboard);
}

TEST(ladder, problems_name_the_rung_and_field_at_fault) {
    EXPECT_FALSE(find_ladder_problem(three_rungs()));
    EXPECT_FALSE(find_ladder_problem(papers_ladder()));
    EXPECT_EQ(find_ladder_problem(ladder{})->what, "a ladder needs at least one rung");

    ladder repeated = three_rungs();
    repeated.rungs[2] = representation::mesh_full;
    EXPECT_EQ(find_ladder_problem(repeated)->rung, 2u);
    EXPECT_EQ(find_ladder_problem(repeated)->field, "rung");

    ladder rising = three_rungs();
    rising.below_px[2] = 250.0f;
    EXPECT_EQ(find_ladder_problem(rising)->rung, 2u);
    EXPECT_EQ(find_ladder_problem(rising)->field, "below_px");

    // 50 x 1.2 = 60 px must stay below 200 x 0.9 = 180 px; 160 x 1.2 = 192 does not.
    ladder overlapping = three_rungs();
    overlapping.below_px[2] = 160.0f;
    EXPECT_EQ(find_ladder_problem(overlapping)->rung, 2u);
    EXPECT_EQ(find_ladder_problem(overlapping)->field, "band");

    ladder unsized = three_rungs();
    unsized.below_px[1] = 0.0f;
    EXPECT_EQ(find_ladder_problem(unsized)->field, "below_px");
    unsized.below_px[1] = NAN;
    EXPECT_EQ(find_ladder_problem(unsized)->field, "below_px");

    ladder not_a_rung = three_rungs();
    not_a_rung.rungs[0] = representation::none;
    EXPECT_EQ(find_ladder_problem(not_a_rung)->rung, 0u);
}

// billboard_cloud | 60 px ± 15 % | points_lines | 12 px ± 25 % | eco_tile_points
ladder to_the_eco_tile() {
    ladder l;
    l.count = 3;
    l.rungs = {representation::billboard_cloud, representation::points, representation::eco_tile};
    l.below_px = {0.0f, 60.0f, 12.0f};
    l.band = {0.0f, 0.15f, 0.25f};
    return l;
}

TEST(ladder, the_eco_tile_rung_ends_a_ladder_right_after_points_and_lines) {
    EXPECT_FALSE(find_ladder_problem(to_the_eco_tile()));
    ladder after_clouds = to_the_eco_tile();
    after_clouds.rungs[1] = representation::crossed_billboard;
    EXPECT_EQ(find_ladder_problem(after_clouds)->rung, 2u);
    EXPECT_EQ(find_ladder_problem(after_clouds)->field, "rung");
    ladder not_last = to_the_eco_tile();
    not_last.count = 4;
    not_last.rungs[3] = representation::crossed_billboard;
    not_last.below_px[3] = 4.0f;
    not_last.band[3] = 0.1f;
    EXPECT_EQ(find_ladder_problem(not_last)->rung, 2u);
    ladder alone;
    alone.count = 1;
    alone.rungs[0] = representation::eco_tile;
    EXPECT_EQ(find_ladder_problem(alone)->rung, 0u);
    EXPECT_EQ(rung_of_name("eco_tile_points"), representation::eco_tile);
}

TEST(ladder, the_eco_tile_share_is_how_far_the_plant_is_into_its_last_band) {
    const ladder l = to_the_eco_tile();
    // Band 12 px ± 25 %: 15 .. 9 px, t = (15 − size) / 6; the tile may draw t of the plant.
    const auto share = [&](float size) {
        const ladder_choice c = choose_rung(l, size);
        return eco_tile_share(c.primary, c.partner, c.partner_fade);
    };
    EXPECT_EQ(share(30.0f), 0.0f);   // points whole
    EXPECT_EQ(share(15.5f), 0.0f);
    EXPECT_NEAR(share(13.5f), 0.25f, 1e-6f);  // t = 1/4: points whole, the tile fading in at 1/2
    EXPECT_NEAR(share(10.5f), 0.75f, 1e-6f);  // t = 3/4: the tile whole, points fading out at 1/2
    EXPECT_EQ(share(8.0f), 1.0f);
    EXPECT_EQ(share(std::nanf("")), 1.0f);
    // Other rungs do not let their tile draw them.
    EXPECT_EQ(share(80.0f), 0.0f);
    EXPECT_EQ(eco_tile_share(representation::billboard_cloud, representation::points, 0.5f), 0.0f);
}

TEST(ladder, the_papers_ladder_runs_from_the_full_mesh_to_the_crossed_billboard) {
    const ladder l = papers_ladder();
    EXPECT_EQ(choose_rung(l, 1e4f).primary, representation::mesh_full);
    EXPECT_EQ(choose_rung(l, 1.0f).primary, representation::crossed_billboard);
    EXPECT_TRUE(l.reaches(representation::billboard_cloud));
    EXPECT_TRUE(l.reaches(representation::points));
    EXPECT_FALSE(l.reaches(representation::mesh_far));
}

}  // namespace
}  // namespace sylva
