// A scenario's shell textures (setup/shell_assets.h; Behrendt 2005 §3.1, §3.4): one slice stack
// per Wang tile, baked from the plants the tiling puts there, seamless across tile borders.
#include "setup/shell_assets.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scenarios/scenario_loader.h"
#include "setup/spawn_scenario.h"
#include "setup/wang_populations.h"

namespace sylva {
namespace {

scenario shrubland() {
    return load_scenario_text(R"({
        "seed": 9,
        "terrain": {"size_m": 96, "resolution": 17, "height_m": 2},
        "wang_tiles": {"tile_size_m": 16, "colours": 2},
        "species": [{"name": "bush", "generator": "shrub", "height_m": 1.6}],
        "populations": [{"species": "bush", "count": 700, "min_spacing_m": 1.2, "placement": "wang_tiles"}]})",
                              "shrubland.json");
}

struct baked {
    scenario s = shrubland();
    scene_assets assets = build_scene_assets(s, nullptr);
    shell_textures shells = build_shell_assets(s, assets, nullptr);
};

const baked& shared() {
    static const baked b;
    return b;
}

float alpha_of_column(const shell_stack& stack, std::uint32_t x, std::uint32_t z) {
    float a = 0.0f;  // seen from above: the slices' coverage composited
    for (std::size_t k = stack.colour.size(); k-- > 0;) {
        const float ak = float(stack.colour[k].at(x, z)[3]) / 255.0f;
        a = a + ak * (1.0f - a);
    }
    return a;
}

TEST(shell_assets, every_tile_is_baked_with_one_slice_height) {
    const baked& b = shared();
    ASSERT_EQ(b.shells.tiles.size(), 16u);
    EXPECT_EQ(b.shells.tile_size_m, 16.0);
    for (const shell_stack& t : b.shells.tiles) {
        EXPECT_EQ(t.colour.size(), 16u);
        EXPECT_FLOAT_EQ(t.slice_height_m, b.shells.tiles[0].slice_height_m);
        EXPECT_EQ(t.colour[0].width, 64u) << "16 m at 0.25 m a texel";
    }
    EXPECT_NEAR(b.shells.tiles[0].slice_height_m * 16.0f, 1.6f * 1.2f, 0.25f) << "the tallest plant at scale_max";
}

// Where the tiling puts a plant, its tile's shell is covered; the shells over a tile's plants
// are denser than over the gaps.
TEST(shell_assets, the_shell_shows_the_plants_the_tiling_places) {
    const baked& b = shared();
    const wang_tile_set set = wang_tile_set_of(b.s, 0, wang_reach_m(b.s, 0, b.assets));
    double under_plants = 0.0;
    std::size_t n = 0;
    for (std::size_t t = 0; t < set.tiles.size(); ++t)
        for (const placement& p : set.tiles[t]) {
            const auto x = std::uint32_t(p.xz.x / 0.25);
            const auto z = std::uint32_t(p.xz.y / 0.25);
            under_plants += alpha_of_column(b.shells.tiles[t], x, z);
            ++n;
        }
    ASSERT_GT(n, 100u);
    double everywhere = 0.0;
    for (const shell_stack& t : b.shells.tiles)
        for (std::uint32_t z = 0; z < 64; ++z)
            for (std::uint32_t x = 0; x < 64; ++x) everywhere += alpha_of_column(t, x, z);
    everywhere /= 16.0 * 64.0 * 64.0;
    EXPECT_GT(under_plants / double(n), 0.8);
    EXPECT_GT(under_plants / double(n), everywhere + 0.1);
}

// Seams: across the border between two tiles the tiling puts side by side, neighbouring texels
// differ no more than neighbouring texels inside the tiles do (the plants that cross it are baked
// into both).
TEST(shell_assets, tiles_meet_without_seams) {
    const baked& b = shared();
    double across = 0.0;
    double inside = 0.0;
    std::size_t n_across = 0;
    std::size_t n_inside = 0;
    for (std::int64_t j = 0; j < 6; ++j)
        for (std::int64_t i = 0; i < 5; ++i) {
            const shell_stack& left = b.shells.tiles[wang_tile_at(b.shells.tiling_seed, i, j, 2)];
            const shell_stack& right = b.shells.tiles[wang_tile_at(b.shells.tiling_seed, i + 1, j, 2)];
            for (std::uint32_t z = 0; z < 64; ++z) {
                across += std::abs(alpha_of_column(left, 63, z) - alpha_of_column(right, 0, z));
                ++n_across;
                inside += std::abs(alpha_of_column(left, 31, z) - alpha_of_column(left, 32, z));
                ++n_inside;
            }
        }
    EXPECT_LE(across / double(n_across), 1.3 * inside / double(n_inside));
}

}  // namespace
}  // namespace sylva
