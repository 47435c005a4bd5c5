// Wang tiles of real plants (models/terrain/wang_tiles.h; Behrendt 2005 §3.4, Cohen et al. 2003,
// corner colours after Lagae & Dutré 2006): valid and deterministic tilings, and plants that keep
// their spacing across every tile border.
#include "models/terrain/wang_tiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <set>

namespace sylva {
namespace {

wang_tile_rules trees() {
    wang_tile_rules rules;
    rules.tile_size_m = 24.0;
    rules.colours = 2;
    rules.min_spacing_m = 3.0f;
    rules.plants_per_m2 = 0.08;  // denser than fits: every region is packed to the spacing
    rules.scale_min = 0.8f;
    rules.scale_max = 1.2f;
    return rules;
}

// r = 2: w = 2, m = 2 + 2/√2 = 3.41421 (each up by a part in a million).
TEST(wang_tiles, margins_are_the_spacing_and_the_spacing_over_root_two_more) {
    const wang_margins g = wang_margins_for(2.0);
    EXPECT_NEAR(g.strip, 2.0, 1e-5);
    EXPECT_NEAR(g.corner, 3.41421, 1e-5);
    EXPECT_GE(std::sqrt(2.0) * (g.corner - g.strip), 2.0) << "strips meeting at a corner are r apart";
}

// Index sw + C(se + C(nw + C ne)): with C = 2, corners (1, 0, 1, 1) are 1 + 2(0 + 2(1 + 2)) = 13.
TEST(wang_tiles, a_tile_index_is_its_four_corner_colours) {
    EXPECT_EQ(wang_tile_index(2, 1, 0, 1, 1), 13u);
    EXPECT_EQ(wang_tile_corners(2, 13), (std::array<std::uint32_t, 4>{1, 0, 1, 1}));
    EXPECT_EQ(wang_tile_index(3, 2, 1, 0, 2), 2u + 3u * (1u + 3u * (0u + 3u * 2u)));
    for (std::uint32_t i = 0; i < 81; ++i) {
        const auto c = wang_tile_corners(3, i);
        EXPECT_EQ(wang_tile_index(3, c[0], c[1], c[2], c[3]), i);
    }
}

// Every shared edge matches: a tile's east corners are its east neighbour's west corners, its
// north corners its north neighbour's south ones; every tile type occurs; the tiling depends
// only on (seed, i, j), whatever order it is asked in, and another seed gives another tiling.
TEST(wang_tiles, the_tiling_is_valid_deterministic_and_uses_every_tile) {
    const std::uint64_t seed = 42;
    std::set<std::uint32_t> used;
    for (std::int64_t j = -20; j < 20; ++j)
        for (std::int64_t i = -20; i < 20; ++i) {
            const auto here = wang_tile_corners(2, wang_tile_at(seed, i, j, 2));
            const auto east = wang_tile_corners(2, wang_tile_at(seed, i + 1, j, 2));
            const auto north = wang_tile_corners(2, wang_tile_at(seed, i, j + 1, 2));
            EXPECT_EQ(here[1], east[0]);  // se = east's sw
            EXPECT_EQ(here[3], east[2]);  // ne = east's nw
            EXPECT_EQ(here[2], north[0]);  // nw = north's sw
            EXPECT_EQ(here[3], north[1]);  // ne = north's se
            used.insert(wang_tile_at(seed, i, j, 2));
        }
    EXPECT_EQ(used.size(), 16u);
    EXPECT_EQ(wang_tile_at(seed, 7, -3, 2), wang_tile_at(seed, 7, -3, 2));
    int differ = 0;
    for (std::int64_t i = 0; i < 64; ++i) differ += wang_tile_at(seed, i, 0, 2) != wang_tile_at(seed + 1, i, 0, 2);
    EXPECT_GT(differ, 16);
}

// Not periodic along a row: no shift of 1..16 tiles repeats the row's tile types.
TEST(wang_tiles, a_row_of_tiles_has_no_short_period) {
    std::vector<std::uint32_t> row;
    for (std::int64_t i = 0; i < 256; ++i) row.push_back(wang_tile_at(9, i, 5, 2));
    for (std::size_t period = 1; period <= 16; ++period) {
        std::size_t same = 0;
        for (std::size_t i = 0; i + period < row.size(); ++i) same += row[i] == row[i + period];
        EXPECT_LT(double(same) / double(row.size() - period), 0.3) << "period " << period;
    }
}

// The minimum spacing holds everywhere in a tiled area, across every tile edge and corner, and
// the area is filled (a packed dart throwing at spacing r leaves about 0.5 / r² plants a m²).
TEST(wang_tiles, plants_keep_their_spacing_across_tile_borders) {
    const wang_tile_rules rules = trees();
    const std::array<double, 4> area{-60.0, -50.0, 84.0, 70.0};
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        SCOPED_TRACE(seed);
        const wang_tile_set set = build_wang_tile_set(rules, seed);
        ASSERT_EQ(set.tiles.size(), 16u);
        const std::vector<placement> plants = place_wang_tiles(set, seed * 31, {-12.0, 0.0}, area);
        const double density = double(plants.size()) / ((area[2] - area[0]) * (area[3] - area[1]));
        EXPECT_GT(density, 0.35 / (3.0 * 3.0));
        double nearest = 1e9;
        std::size_t across_borders = 0;
        const auto tile = [](glm::dvec2 p) { return glm::ivec2(glm::floor((p - glm::dvec2(-12.0, 0.0)) / 24.0)); };
        for (std::size_t a = 0; a < plants.size(); ++a)
            for (std::size_t b = a + 1; b < plants.size(); ++b) {
                const double d = glm::length(plants[a].xz - plants[b].xz);
                nearest = std::min(nearest, d);
                if (d < 4.0 && tile(plants[a].xz) != tile(plants[b].xz)) ++across_borders;
            }
        EXPECT_GE(nearest, 3.0);
        EXPECT_GT(across_borders, 50u) << "neighbours across borders are as close as inside tiles";
        for (const placement& p : plants) {
            EXPECT_GE(p.xz.x, area[0]);
            EXPECT_LT(p.xz.x, area[2]);
            EXPECT_GE(p.scale, 0.8f);
            EXPECT_LE(p.scale, 1.2f);
        }
    }
}

// A tile type is the same plants wherever it lies, in tile coordinates [0, T)², and the set is
// the same for the same seed.
TEST(wang_tiles, a_tile_type_is_the_same_plants_wherever_it_lies) {
    const wang_tile_set set = build_wang_tile_set(trees(), 5);
    const wang_tile_set again = build_wang_tile_set(trees(), 5);
    for (std::size_t t = 0; t < set.tiles.size(); ++t) {
        ASSERT_EQ(set.tiles[t].size(), again.tiles[t].size());
        for (std::size_t k = 0; k < set.tiles[t].size(); ++k) {
            EXPECT_EQ(set.tiles[t][k].xz, again.tiles[t][k].xz);
            EXPECT_EQ(set.tiles[t][k].seed, again.tiles[t][k].seed);
            EXPECT_GE(set.tiles[t][k].xz.x, 0.0);
            EXPECT_LT(set.tiles[t][k].xz.y, 24.0);
        }
    }
    // Two lattice tiles of the same type hold the same plants, shifted by their offset.
    const std::uint64_t seed = 3;
    std::int64_t other = -1;
    for (std::int64_t i = 1; i < 64 && other < 0; ++i)
        if (wang_tile_at(seed, i, 0, 2) == wang_tile_at(seed, 0, 0, 2)) other = i;
    ASSERT_GT(other, 0);
    const auto first = place_wang_tiles(set, seed, {0.0, 0.0}, {0.0, 0.0, 24.0, 24.0});
    const auto second = place_wang_tiles(set, seed, {0.0, 0.0}, {24.0 * double(other), 0.0, 24.0 * double(other + 1), 24.0});
    ASSERT_EQ(first.size(), second.size());
    for (std::size_t k = 0; k < first.size(); ++k) {
        EXPECT_NEAR(second[k].xz.x - first[k].xz.x, 24.0 * double(other), 1e-9);
        EXPECT_EQ(second[k].yaw, first[k].yaw);
    }
}

// Every plant of a tiling within the reach of a tile is one its colours fix: its own, or one of
// its `reaching` (the rest of its corner squares and edge strips), whatever tiles lie around it.
TEST(wang_tiles, every_plant_that_can_reach_a_tile_is_fixed_by_its_colours) {
    wang_tile_rules rules = trees();
    rules.reach_m = 5.0f;
    rules.tile_size_m = 28.0;  // 2 (m + w) = 2 (5 + 2.12 + 5) = 24.2
    const wang_tile_set set = build_wang_tile_set(rules, 7);
    const std::uint64_t seed = 13;
    const std::vector<placement> all = place_wang_tiles(set, seed, {0.0, 0.0}, {-56.0, -56.0, 112.0, 112.0});
    std::size_t checked = 0;
    for (std::int64_t j = 0; j < 3; ++j)
        for (std::int64_t i = 0; i < 3; ++i) {
            const std::uint32_t type = wang_tile_at(seed, i, j, 2);
            const glm::dvec2 corner{28.0 * double(i), 28.0 * double(j)};
            std::vector<glm::dvec2> fixed;
            for (const placement& p : set.tiles[type]) fixed.push_back(p.xz);
            for (const placement& p : set.reaching[type]) fixed.push_back(p.xz);
            for (const placement& p : all) {
                const glm::dvec2 local = p.xz - corner;
                if (local.x < -5.0 || local.x >= 33.0 || local.y < -5.0 || local.y >= 33.0) continue;
                const bool found = std::any_of(fixed.begin(), fixed.end(),
                                               [&](glm::dvec2 q) { return glm::length(q - local) < 1e-9; });
                EXPECT_TRUE(found) << "tile " << i << "," << j << " plant at " << local.x << "," << local.y;
                ++checked;
            }
        }
    EXPECT_GT(checked, 300u);
}

TEST(wang_tiles, rules_that_cannot_make_a_set_say_why) {
    wang_tile_rules rules = trees();
    rules.tile_size_m = 10.0;  // needs 2 (m + w) = 2 (5.12 + 3) = 16.24 m for a 3 m spacing
    EXPECT_NE(wang_rules_problem(rules).find("too small"), std::string::npos);
    EXPECT_THROW(build_wang_tile_set(rules, 1), std::invalid_argument);
    rules = trees();
    rules.colours = 1;
    EXPECT_NE(wang_rules_problem(rules).find("colours"), std::string::npos);
    EXPECT_TRUE(wang_rules_problem(trees()).empty());
}

}  // namespace
}  // namespace sylva
