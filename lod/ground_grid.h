#pragma once
// Geometrical mip-mapping (de Boer 2000, "Fast Terrain Rendering Using Geometrical MipMapping"):
// a terrain tile is drawn from a grid of every 2^g-th height sample, the coarsest whose vertical
// error, seen from the tile's nearest point, shows as at most a tolerance in pixels. The ground
// (components/ground_tile.h) and the shells' slices (components/shell_tile.h) both choose their
// grids so.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace sylva {

// The grids per tile: strides 1, 2, 4, ... of the terrain's samples (at most this many).
inline constexpr std::size_t k_max_ground_grids = 8;

// How many grids a tile of `tile_cells` cells per side has: strides 1, 2, 4, ... up to the first
// that leaves it one cell, at most k_max_ground_grids.
constexpr std::size_t ground_grid_count(std::uint32_t tile_cells) {
    std::size_t grids = 1;
    for (std::uint32_t stride = 2; grids < k_max_ground_grids && stride / 2 < tile_cells;
         stride *= 2)
        ++grids;
    return grids;
}

// The coarsest grid g, walking up from grid 0 while the next one's error e_{g+1} (metres, by
// grid: `grid_error_m`, grid 0 the terrain's own) seen from `nearest_m` projects to at most
// `tolerance_px`: e·pixels_per_radian / d ≤ tolerance (de Boer 2000's screen-space error, the
// vertical displacement seen side-on, its largest). Grid 0 when `grid_error_m` holds one grid.
std::uint8_t coarsest_ground_grid(std::span<const float> grid_error_m, float nearest_m,
                                  float pixels_per_radian, float tolerance_px);

// How deep each tile's skirts hang on one grid (models/terrain/terrain.h terrain_tile_skirts),
// tiles row-major, `tiles_per_side` per side: a skirt must reach from its edge below its
// neighbour's edge, and each grid strays from the terrain by at most its error, so tile t's
// hangs e_t(its grid) + the largest e_n(coarsest grid) of its four neighbours n (whatever grids
// they are on). `errors` are the tiles' errors on the skirts' grid, `coarsest` on the coarsest.
std::vector<float> ground_skirt_depths(std::span<const float> errors,
                                       std::span<const float> coarsest,
                                       std::uint32_t tiles_per_side);

}  // namespace sylva
