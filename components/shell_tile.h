#pragma once
// Behrendt 2005 §3.3: one terrain tile of the shell layer, an entity per tile of the terrain
// mesh (scene_assets::terrain_meshes order) when the scene has shells. Its slices are drawn from
// a grid of the terrain's samples as coarse as the distance allows (geometric mip-mapping,
// de Boer 2000: the coarsest whose vertical error projects under k_shell_ground_error_px). Writer: update_shells
// (systems/update_shells_system.h), every frame, tiles in parallel; read by the submit system,
// whose shell pass draws each tile at its level.
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

#include "lod/shell_levels.h"

namespace sylva {

// The slices' grids per tile: strides 1, 2, 4, ... of the terrain's samples (at most this many).
inline constexpr std::size_t k_shell_grid_strides = 8;

// How many grids a tile of `tile_cells` cells per side has: strides 1, 2, 4, ... up to the first
// that leaves it one cell, at most k_shell_grid_strides.
constexpr std::size_t shell_grid_count(std::uint32_t tile_cells) {
    std::size_t grids = 1;
    for (std::uint32_t stride = 2; grids < k_shell_grid_strides && stride / 2 < tile_cells; stride *= 2) ++grids;
    return grids;
}

struct shell_tile {
    glm::vec3 centre{0.0f};  // terrain-local, of the tile's bounding sphere
    float radius = 0.0f;     // holds the tile's slices, however high and slanted
    shell_level level;       // the pyramid level its nearest point asks, and the merge
    bool visible = false;    // its sphere touches the view frustum
    // By grid (stride 2^k), how far its surface strays vertically from the terrain
    // (models/terrain/terrain.h terrain_tile_errors); `grids` of them.
    std::array<float, k_shell_grid_strides> grid_error_m{};
    std::uint8_t grids = 1;
    std::uint8_t grid = 0;  // this frame's: the coarsest whose error shows under a pixel
};

}  // namespace sylva
