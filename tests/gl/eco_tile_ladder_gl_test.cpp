// A ladder's last step, points and lines -> eco_tile_points (Deussen 2002 §5.3 and §6.2; lod/ladder.h,
// systems/aggregate_eco_tiles_system.h), drawn by the GL renderer: the patch of shrubs of
// tests/app/data/tile_handover.json goes over from its plants' own points to its eco tiles'
// aggregated sets as the camera backs away, and across the band the patch does not thin out: its
// ID-buffer coverage, times distance², never falls far below what either side covers whole, and
// inside the band both are drawn.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/scenario_player.h"
#include "components/transform.h"
#include "gl_test_support.h"
#include "ladder_walk.h"
#include "lod/ladder.h"
#include "lod/point_line_lod.h"
#include "resources/playback.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_width = 480;
constexpr std::uint32_t k_height = 270;
constexpr float k_switch_px = 10.0f;  // eco_tile_points below 10 px, band ± 25 %
constexpr float k_band = 0.25f;

scenario patch_on_a_ladder() {
    scenario s = load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "tests/app/data/tile_handover.json");
    s.width = k_width;
    s.height = k_height;
    s.lod.representation = "ladder";
    s.lod.ladder = {{"points_lines", 0.0f, k_default_band}, {"eco_tile_points", k_switch_px, k_band}};
    return s;
}

using testing::drawn;
using testing::walk_sample;

class patch_to_its_tiles : public ::testing::Test {
protected:
    patch_to_its_tiles() : m_walk(patch_on_a_ladder()) {}
    // The first shrub's size, the walk's distance from the patch's centre.
    double distance_for(float size_px) { return m_walk.distance_for(size_px); }
    walk_sample at(double distance_m) { return m_walk.at(distance_m); }
    testing::ladder_walk m_walk;
};

TEST_F(patch_to_its_tiles, the_handover_to_the_tile_sets_does_not_thin_the_patch_out) {
    SYLVA_REQUIRE_GL();
    const float s = k_switch_px, h = k_band;
    // Edges well outside the first shrub's band: the patch is 24 m deep and its shrubs' sizes
    // differ, so every shrub is out of its band only some way beyond.
    const walk_sample before = at(distance_for(s * (1.0f + h) * 1.6f));
    const walk_sample after = at(distance_for(s * (1.0f - h) * 0.6f));
    EXPECT_GT(drawn(before, representation::points), 0u);
    EXPECT_EQ(drawn(before, representation::eco_tile), 0u);
    EXPECT_EQ(before.record.aggregated_tiles, 0u);
    EXPECT_EQ(drawn(after, representation::points), 0u);
    EXPECT_GT(drawn(after, representation::eco_tile), 0u);
    EXPECT_GT(after.record.aggregated_tiles, 0u);
    ASSERT_GT(after.pixels, 100u);
    const double floor = 0.85 * std::min(before.normalised(), after.normalised());
    std::printf("points -> eco_tile_points: coverage x d² at the edges %.0f, %.0f; inside:", before.normalised(),
                after.normalised());
    std::size_t both = 0;
    for (int k = 1; k < 10; ++k) {
        const float size = s * (1.0f + h - 2.0f * h * float(k) / 10.0f);
        const walk_sample in = at(distance_for(size));
        std::printf(" %.0f", in.normalised());
        EXPECT_GE(in.normalised(), floor) << "at " << size << " px (" << in.distance_m << " m)";
        // The shrubs of one leaf tile differ in size: the tile draws its share once all of them
        // are in the band, and the plants their own points for the rest.
        both += drawn(in, representation::points) > 0 && in.record.aggregated_tiles > 0;
    }
    std::printf("\n");
    EXPECT_GE(both, 3u) << "the band drew the points and the tile sets together in too few frames";
}

}  // namespace
}  // namespace sylva
