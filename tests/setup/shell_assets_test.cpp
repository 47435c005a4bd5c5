// A scenario's shell textures (setup/shell_assets.h; Behrendt 2005 §3.1, §3.4): one slice stack
// per Wang tile, baked from the plants the tiling puts there, seamless across tile borders.
#include "setup/shell_assets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "models/bake/transfer_pages.h"
#include "scenarios/scenario_loader.h"
#include "setup/spawn_scenario.h"
#include "setup/wang_populations.h"

namespace sylva {
namespace {

scenario shrubland(std::uint32_t colours = 2) {
    scenario s = load_scenario_text(R"({
        "seed": 9,
        "terrain": {"size_m": 96, "resolution": 17, "height_m": 2},
        "wang_tiles": {"tile_size_m": 16, "colours": 2},
        "species": [{"name": "bush", "generator": "shrub", "height_m": 1.6}],
        "populations": [{"species": "bush", "count": 700, "min_spacing_m": 1.2, "placement": "wang_tiles"}]})",
                                    "shrubland.json");
    s.wang_tiles.colours = colours;
    return s;
}

struct baked {
    explicit baked(std::uint32_t colours = 2) : s(shrubland(colours)) {}
    scenario s;
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

// Behrendt 2005 §4 on the shells: the slices of SH-lit plants carry the plants' transfer, at a
// quarter of the colour's texels a side, five pages a slice. Its band-0 coefficient is the
// visible fraction of the sky's cosine lobe: at most π·Y₀₀ = 0.886 (an unoccluded upward
// surface), and lower deep in the shrubs than at their tops (the self-shadowing the transfer
// holds). A normal-lit species among the tiled ones, or shells.lighting "normal_mapped",
// keeps the normals.
TEST(shell_assets, the_slices_of_sh_lit_plants_carry_their_transfer) {
    scenario s = shrubland();
    s.lod.lighting = "sh";
    s.populations[0].count = 300;
    const scene_assets assets = build_scene_assets(s, nullptr);
    const shell_textures shells = build_shell_assets(s, assets, nullptr);
    ASSERT_EQ(shells.tiles.size(), 16u);
    double sum_low = 0.0, sum_high = 0.0;
    std::size_t n_low = 0, n_high = 0;
    for (const shell_stack& t : shells.tiles) {
        ASSERT_EQ(t.transfer.size(), t.colour.size() * k_transfer_pages);
        EXPECT_EQ(t.transfer.front().width, 16u) << "64 colour texels / 4";
        for (std::size_t k = 0; k < t.colour.size(); ++k) {
            const image_rgba8& coverage_page = t.transfer[k * k_transfer_pages + k_shell_transfer_coverage_channel / 4];
            const image_rgba8& dc_page = t.transfer[k * k_transfer_pages];
            for (std::uint32_t z = 0; z < 16; ++z)
                for (std::uint32_t x = 0; x < 16; ++x) {
                    if (coverage_page.at(x, z)[k_shell_transfer_coverage_channel % 4] < 128) continue;
                    const float dc = decode_transfer(dc_page.at(x, z)[0]);
                    EXPECT_LE(dc, 0.886f + 0.02f);
                    (k < t.colour.size() / 2 ? sum_low : sum_high) += dc;
                    ++(k < t.colour.size() / 2 ? n_low : n_high);
                }
        }
    }
    ASSERT_GT(n_low, 50u);
    ASSERT_GT(n_high, 50u);
    EXPECT_GT(sum_high / double(n_high), sum_low / double(n_low) + 0.05)
        << "the tops see more sky than the inside: " << sum_high / double(n_high) << " against " << sum_low / double(n_low);
    scenario normals = s;
    normals.shells.lighting = "normal_mapped";
    EXPECT_TRUE(build_shell_assets(normals, assets, nullptr).tiles.front().transfer.empty());
    scenario mixed = s;
    mixed.species.push_back(mixed.species.front());
    mixed.species.back().name = "fern";
    mixed.species.back().lighting = "normal_mapped";
    mixed.populations.push_back(mixed.populations.front());
    mixed.populations.back().species = "fern";
    const scene_assets mixed_assets = build_scene_assets(mixed, nullptr);
    EXPECT_TRUE(build_shell_assets(mixed, mixed_assets, nullptr).tiles.front().transfer.empty());
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

// A slice's mip level `level` as GL builds it (glGenerateMipmap: each texel the mean of the 2x2
// below it), coverage only.
std::vector<float> alpha_mip(const image_rgba8& slice, std::uint32_t level, std::uint32_t& side) {
    side = slice.width;
    std::vector<float> a(std::size_t(side) * side);
    for (std::uint32_t z = 0; z < side; ++z)
        for (std::uint32_t x = 0; x < side; ++x) a[std::size_t(z) * side + x] = float(slice.at(x, z)[3]) / 255.0f;
    for (std::uint32_t l = 0; l < level; ++l) {
        const std::uint32_t half = side / 2;
        std::vector<float> next(std::size_t(half) * half);
        for (std::uint32_t z = 0; z < half; ++z)
            for (std::uint32_t x = 0; x < half; ++x)
                next[std::size_t(z) * half + x] = 0.25f * (a[std::size_t(2 * z) * side + 2 * x] + a[std::size_t(2 * z) * side + 2 * x + 1] +
                                                           a[std::size_t(2 * z + 1) * side + 2 * x] +
                                                           a[std::size_t(2 * z + 1) * side + 2 * x + 1]);
        a = std::move(next);
        side = half;
    }
    return a;
}

// Behrendt 2005 §3.4 asks how mip levels stay seamless: each layer's mips are its own, and a tile's
// border texels hold the plants across it, so at every level the texels on either side of a border
// differ no more than neighbours inside a tile (slice by slice, 64 texels down to 2). Baked
// without the plants that reach in, levels 0 and 1 fail.
TEST(shell_assets, tiles_meet_without_seams_at_every_mip_level) {
    const baked& b = shared();
    for (std::uint32_t level = 0; level < 6; ++level) {
        double across = 0.0, inside = 0.0;
        for (std::int64_t j = 0; j < 6; ++j)
            for (std::int64_t i = 0; i < 5; ++i) {
                const shell_stack& left = b.shells.tiles[wang_tile_at(b.shells.tiling_seed, i, j, 2)];
                const shell_stack& right = b.shells.tiles[wang_tile_at(b.shells.tiling_seed, i + 1, j, 2)];
                for (std::size_t k = 0; k < left.colour.size(); ++k) {
                    std::uint32_t n = 0;
                    const std::vector<float> l = alpha_mip(left.colour[k], level, n);
                    const std::vector<float> r = alpha_mip(right.colour[k], level, n);
                    for (std::uint32_t z = 0; z < n; ++z) {
                        across += std::abs(l[std::size_t(z) * n + n - 1] - r[std::size_t(z) * n]);
                        inside += std::abs(l[std::size_t(z) * n + n / 2 - 1] - l[std::size_t(z) * n + n / 2]);
                    }
                }
            }
        EXPECT_LE(across, 1.3 * inside) << "mip level " << level;
    }
}

// Luminance of the shells seen from above over a field of tiles (each tile's 16 slices composited
// top first, at mip level 3: 8 texels a tile), with a tile chosen by `tile_at(i, j)`.
std::vector<double> far_field_luminance(const baked& b, std::int64_t tiles, std::uint32_t& side,
                                        std::size_t (*tile_at)(const baked&, std::int64_t, std::int64_t)) {
    const std::uint32_t n = 8;
    side = std::uint32_t(tiles) * n;
    std::vector<double> image(std::size_t(side) * side);
    for (std::int64_t j = 0; j < tiles; ++j)
        for (std::int64_t i = 0; i < tiles; ++i) {
            const shell_stack& stack = b.shells.tiles[tile_at(b, i, j)];
            std::vector<std::vector<float>> luma, alpha;
            for (const image_rgba8& slice : stack.colour) {
                std::uint32_t m = 0;
                image_rgba8 luminance = slice;  // luma of the premultiplied colour in the alpha channel
                for (std::size_t t = 0; t < std::size_t(slice.width) * slice.height; ++t)
                    luminance.texels[4 * t + 3] = std::uint8_t(
                        (54 * slice.texels[4 * t] + 183 * slice.texels[4 * t + 1] + 19 * slice.texels[4 * t + 2]) >> 8);
                luma.push_back(alpha_mip(luminance, 3, m));
                alpha.push_back(alpha_mip(slice, 3, m));
            }
            for (std::uint32_t z = 0; z < n; ++z)
                for (std::uint32_t x = 0; x < n; ++x) {
                    double c = 0.0, a = 0.0;
                    for (std::size_t k = luma.size(); k-- > 0;) {  // the top slice first
                        c += (1.0 - a) * luma[k][std::size_t(z) * n + x];
                        a += (1.0 - a) * alpha[k][std::size_t(z) * n + x];
                    }
                    image[(std::size_t(j) * n + z) * side + std::size_t(i) * n + x] = c;
                }
        }
    return image;
}

// The normalised autocorrelation of `image` along x at a lag of `lag` texels.
double autocorrelation_x(const std::vector<double>& image, std::uint32_t side, std::uint32_t lag) {
    double mean = 0.0;
    for (double v : image) mean += v;
    mean /= double(image.size());
    double num = 0.0, den = 0.0;
    for (std::uint32_t z = 0; z < side; ++z)
        for (std::uint32_t x = 0; x + lag < side; ++x)
            num += (image[std::size_t(z) * side + x] - mean) * (image[std::size_t(z) * side + x + lag] - mean);
    for (double v : image) den += (v - mean) * (v - mean);
    return num / den * double(side) / double(side - lag);
}

// Repetition (§3.4: Wang tiles limit it): over 16 x 16 tiles the far field's luminance correlates
// with itself one tile period (8 texels) away, against the mean at lags 5, 6, 10 and 11. One tile
// repeated everywhere peaks there (1.00 against -0.11). Three corner colours (81 tiles): no peak
// (0.04 against -0.01). Two (16 tiles): a weak one (0.19 against -0.01), because the corner
// squares' plants, one set per corner colour, recur at every lattice corner.
TEST(shell_assets, the_tiling_shows_no_peak_at_the_tile_period) {
    const auto peak_and_around = [](const baked& b, std::size_t (*tile_at)(const baked&, std::int64_t, std::int64_t)) {
        std::uint32_t side = 0;
        const std::vector<double> image = far_field_luminance(b, 16, side, tile_at);
        double around = 0.0;
        for (std::uint32_t lag : {5u, 6u, 10u, 11u}) around += autocorrelation_x(image, side, lag) / 4.0;
        return std::pair(autocorrelation_x(image, side, 8), around);
    };
    const auto wang = [](const baked& c, std::int64_t i, std::int64_t j) {
        return std::size_t(wang_tile_at(c.shells.tiling_seed, i, j, c.shells.colours));
    };
    const auto [periodic, periodic_around] =
        peak_and_around(shared(), [](const baked&, std::int64_t, std::int64_t) { return std::size_t(0); });
    EXPECT_GT(periodic, periodic_around + 0.5) << "one tile repeated: a peak at its period";
    const auto [two, two_around] = peak_and_around(shared(), wang);
    EXPECT_LT(two - two_around, 0.25 * (periodic - periodic_around)) << "two colours: a quarter of it at most";
    const baked three(3);
    ASSERT_EQ(three.shells.tiles.size(), 81u);
    const auto [peak, around] = peak_and_around(three, wang);
    EXPECT_LT(peak, around + 0.1) << "three colours: none";
}

}  // namespace
}  // namespace sylva
