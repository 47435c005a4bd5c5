#include "lod/ground_grid.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "models/terrain/terrain.h"

namespace sylva {
namespace {

// A tile's grids: strides 1, 2, 4, ... up to the first that leaves one cell (32 cells: 1 .. 32,
// six grids; 4 cells: 1, 2, 4; one cell: the terrain's own), at most eight.
TEST(ground_grid, a_tile_has_a_grid_per_stride_down_to_one_cell) {
    EXPECT_EQ(ground_grid_count(32), 6u);
    EXPECT_EQ(ground_grid_count(4), 3u);
    EXPECT_EQ(ground_grid_count(5), 4u);  // 1, 2, 4, 8: stride 8 leaves one (short) cell
    EXPECT_EQ(ground_grid_count(1), 1u);
    EXPECT_EQ(ground_grid_count(100000), k_max_ground_grids);
}

// By hand, at 270 pixels over 0.96 rad (281.25 px/rad) and half a pixel: grid g is allowed
// from d = e_g·281.25 / 0.5. Grid errors 0.2, 0.5 and 3 m are allowed from 112.5, 281.25 and
// 1687.5 m.
TEST(ground_grid, the_coarsest_grid_whose_error_shows_under_the_tolerance) {
    const std::array<float, 4> errors{0.0f, 0.2f, 0.5f, 3.0f};
    const float ppr = 281.25f;
    EXPECT_EQ(coarsest_ground_grid(errors, 100.0f, ppr, 0.5f), 0u);
    EXPECT_EQ(coarsest_ground_grid(errors, 112.5f, ppr, 0.5f), 1u);
    EXPECT_EQ(coarsest_ground_grid(errors, 200.0f, ppr, 0.5f), 1u);
    EXPECT_EQ(coarsest_ground_grid(errors, 300.0f, ppr, 0.5f), 2u);
    EXPECT_EQ(coarsest_ground_grid(errors, 1687.0f, ppr, 0.5f), 2u);
    EXPECT_EQ(coarsest_ground_grid(errors, 2000.0f, ppr, 0.5f), 3u);
    // A tolerance twice as large allows each grid from half the distance.
    EXPECT_EQ(coarsest_ground_grid(errors, 150.0f, ppr, 1.0f), 2u);
    // One grid: always the terrain's own.
    EXPECT_EQ(coarsest_ground_grid(std::span(errors).first(1), 1e6f, ppr, 0.5f), 0u);
}

// The walk stops at the first grid that shows: a coarser one with a smaller error (a flat patch
// the coarse grid happens to fit) is not reached past a finer one that would show.
TEST(ground_grid, the_walk_stops_at_the_first_grid_that_shows) {
    const std::array<float, 3> errors{0.0f, 1.0f, 0.1f};
    EXPECT_EQ(coarsest_ground_grid(errors, 100.0f, 281.25f, 0.5f), 0u);
}

// By hand: 2 x 2 tiles whose coarsest errors are 1, 2, 3, 4 (tile 0 at -x -z, 1 at +x, 2 at +z):
// tile 0's neighbours are 1 and 2 (largest 3), tile 3's are 1 and 2 as well; tile 1's are 0 and
// 3 (4), tile 2's too.
TEST(ground_grid, a_skirt_hangs_its_own_error_and_its_neighbours_largest_coarsest_error) {
    const std::vector<float> coarsest{1.0f, 2.0f, 3.0f, 4.0f};
    const std::vector<float> errors{0.5f, 0.0f, 0.25f, 1.0f};
    EXPECT_EQ(ground_skirt_depths(errors, coarsest, 2),
              (std::vector<float>{3.5f, 4.0f, 4.25f, 4.0f}));
    EXPECT_EQ(ground_skirt_depths(std::vector<float>{0.5f}, std::vector<float>{1.0f}, 1),
              std::vector<float>{0.5f});
    EXPECT_THROW(ground_skirt_depths(errors, coarsest, 3), std::invalid_argument);
}

// The skirts close every crack: two tiles of a rough terrain side by side (16 cells each), on
// every pair of grids, along their common edge. Both edges are piecewise linear with breaks at
// the finer samples, so at each sample the higher edge's skirt must reach the lower edge.
TEST(ground_grid, the_higher_edges_skirt_reaches_the_lower_edge_on_every_pair_of_grids) {
    const heightfield f = generate_terrain(320.0, 33, 60.0f, 6, 0.02f, 11);
    const std::uint32_t tiles = 2, cells = 16;
    const std::size_t grids = ground_grid_count(cells);
    std::vector<std::vector<float>> errors;
    for (std::size_t g = 0; g < grids; ++g)
        errors.push_back(terrain_tile_errors(f, tiles, 1u << g));
    ASSERT_GT(errors.back()[0], 1.0f);  // rough enough for the edges to part
    // The edge between tile 0 (columns 0..16) and tile 1 (16..32) along rows 0..16, on a grid.
    auto edge_height = [&](std::uint32_t stride, std::uint32_t row) {
        const std::uint32_t below = row / stride * stride, above = std::min(below + stride, cells);
        if (below == row) return f.at(cells, row);
        const float u = float(row - below) / float(above - below);
        return f.at(cells, below) + u * (f.at(cells, above) - f.at(cells, below));
    };
    for (std::size_t g0 = 0; g0 < grids; ++g0)
        for (std::size_t g1 = 0; g1 < grids; ++g1) {
            SCOPED_TRACE(testing::Message() << "grids " << g0 << " and " << g1);
            const float d0 = ground_skirt_depths(errors[g0], errors.back(), tiles)[0];
            const float d1 = ground_skirt_depths(errors[g1], errors.back(), tiles)[1];
            for (std::uint32_t row = 0; row <= cells; ++row) {
                const float h0 = edge_height(1u << g0, row), h1 = edge_height(1u << g1, row);
                if (h0 > h1)
                    EXPECT_LE(h0 - d0, h1) << "row " << row;
                else
                    EXPECT_LE(h1 - d1, h0) << "row " << row;
            }
        }
}

}  // namespace
}  // namespace sylva
