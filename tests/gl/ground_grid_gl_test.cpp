// The ground on coarser grids far away (geometric mip-mapping, components/ground_tile.h): a
// rough terrain seen obliquely, its tiles on several grids at once, against the same frame on
// the terrain's own samples everywhere. Where neighbouring tiles are on different grids their
// edges part; the skirts (models/terrain/terrain.h terrain_tile_skirts) must fill those cracks,
// so no pixel shows the sky through the ground.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "app/scenario_player.h"
#include "components/ground_tile.h"
#include "gl_test_support.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

// Hills 80 m high on 1 km in 16 x 16 tiles, seen from 100 m above the centre looking 45 degrees
// down, so the view holds ground only (its top edge meets the ground within 400 m). One shrub, in
// a corner out of view. `max_error_px` 0: every tile on its own samples.
scenario hills(float max_error_px) {
    scenario s = load_scenario_text(R"({
        "seed": 4, "resolution": [320, 240], "frames": 1,
        "terrain": {"size_m": 1000, "resolution": 257, "height_m": 80, "octaves": 5, "frequency": 0.004,
                    "tiles_per_side": 16},
        "species": [{"name": "bush", "generator": "shrub", "height_m": 1.0}],
        "populations": [{"species": "bush", "count": 1, "area": [480, 480, 490, 490]}],
        "camera": {"keyframes": [{"t": 0, "position": [0, 100, 0], "target": [40, 0, 40], "fov_deg": 50,
                                  "relative_to_terrain": true}]},
        "render": {"shadows": false}})",
                                    "hills.json");
    s.terrain.max_error_px = max_error_px;
    return s;
}

// How much bluer than green a pixel is: the hazy sky is (about +0.07 here), the fogged green
// ground is not (at most about -0.07).
float blueness(const image_rgba8& image, std::size_t pixel) {
    const std::uint8_t* p = &image.texels[4 * pixel];
    return (float(p[2]) - float(p[1])) / 255.0f;
}

TEST(ground_grid_gl, skirts_close_the_cracks_between_tiles_on_different_grids) {
    SYLVA_REQUIRE_GL();
    scenario_player exact(hills(0.0f), 2, testing::shared_gl_context());
    exact.step();
    const image_rgba8 reference = exact.capture();
    const auto& exact_tiles = exact.world().table<ground_tile>();
    ASSERT_EQ(exact_tiles.size(), 256u);
    for (std::size_t t = 0; t < exact_tiles.size(); ++t) ASSERT_EQ(exact_tiles.data()[t].grid, 0u);

    scenario_player coarse(hills(8.0f), 2, testing::shared_gl_context());
    coarse.step();
    const image_rgba8 image = coarse.capture();
    std::set<int> grids;
    const auto& tiles = coarse.world().table<ground_tile>();
    for (std::size_t t = 0; t < tiles.size(); ++t) grids.insert(tiles.data()[t].grid);
    ASSERT_GE(grids.size(), 3u) << "the tiles are on several grids at once";

    // A crack shows the sky: a pixel bluer than any of the reference's (which shows ground only).
    // Without the skirts, 168 such pixels here (cracks along far tile edges); with them none.
    const std::size_t pixels = reference.texels.size() / 4;
    float bluest = -1.0f;
    for (std::size_t i = 0; i < pixels; ++i) bluest = std::max(bluest, blueness(reference, i));
    ASSERT_LT(bluest, 0.04f) << "the reference shows ground only";
    std::size_t cracks = 0;
    for (std::size_t i = 0; i < pixels; ++i) cracks += blueness(image, i) > bluest + 0.02f;
    EXPECT_EQ(cracks, 0u) << "pixels showing the sky through the ground";
}

// The coarser grids are lit by the terrain's own normals (shaders/mesh.frag ground_normal), so
// what they change is the ground's shape within the tolerance, not its shading: the mean colour
// difference from the frame on the terrain's own samples stays small.
TEST(ground_grid_gl, coarser_grids_keep_the_terrains_shading) {
    SYLVA_REQUIRE_GL();
    scenario_player exact(hills(0.0f), 2, testing::shared_gl_context());
    exact.step();
    const image_rgba8 reference = exact.capture();
    scenario_player coarse(hills(8.0f), 2, testing::shared_gl_context());
    coarse.step();
    const image_rgba8 image = coarse.capture();
    double sum = 0.0;
    for (std::size_t i = 0; i < reference.texels.size(); ++i)
        if (i % 4 != 3) sum += std::abs(int(reference.texels[i]) - int(image.texels[i])) / 255.0;
    const double mean = sum / double(reference.texels.size() / 4 * 3);
    // Measured 0.00935 (of 1, per channel); lit by the coarse grid's own vertex normals 0.01245.
    EXPECT_LT(mean, 0.0108);
}

}  // namespace
}  // namespace sylva
