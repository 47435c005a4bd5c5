#pragma once
// Behrendt 2005 §3.3: one terrain tile of the shell layer, an entity per tile of the terrain
// mesh (scene_assets::terrain_meshes order) when the scene has shells. Its slices are drawn from
// a grid of the terrain's samples as coarse as the distance allows (geometric mip-mapping,
// de Boer 2000; lod/ground_grid.h: the coarsest whose vertical error projects under
// k_shell_ground_error_px). Writer: update_shells (systems/update_shells_system.h), every frame,
// tiles in parallel; read by the submit system, whose shell pass draws each tile at its level.
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

#include "lod/ground_grid.h"
#include "lod/shell_levels.h"

namespace sylva {

struct shell_tile {
    glm::vec3 centre{0.0f};  // terrain-local, of the tile's bounding sphere
    float radius = 0.0f;     // holds the tile's slices, however high and slanted
    shell_level level;       // the pyramid level its nearest point asks, and the merge
    bool visible = false;    // its sphere touches the view frustum
    // By grid (stride 2^k), how far its surface strays vertically from the terrain
    // (models/terrain/terrain.h terrain_tile_errors); `grids` of them.
    std::array<float, k_max_ground_grids> grid_error_m{};
    std::uint8_t grids = 1;
    std::uint8_t grid = 0;  // this frame's: the coarsest whose error shows under a pixel
};

}  // namespace sylva
