#pragma once
// One tile of the ground: an entity per tile of the terrain mesh (scene_assets::terrain_meshes
// order), drawn from a grid of the terrain's samples as coarse as the distance allows (geometric
// mip-mapping, de Boer 2000; lod/ground_grid.h), with skirts where a neighbour's grid differs.
// Writer: select_ground_grid (systems/select_ground_grid_system.h), every frame, tiles in
// parallel; read by the submit system, whose draw commands draw each tile at its grid in the
// view and in every shadow cascade.
#include <array>
#include <cstdint>
#include <glm/ext/vector_double3.hpp>

#include "lod/ground_grid.h"

namespace sylva {

struct ground_tile {
    glm::dvec3 centre{0.0};  // world position of the tile's bounding sphere's centre
    float radius = 0.0f;
    // By grid (stride 2^g), how far its surface strays vertically from the terrain
    // (models/terrain/terrain.h terrain_tile_errors); `grids` of them.
    std::array<float, k_max_ground_grids> grid_error_m{};
    std::uint8_t grids = 1;
    std::uint8_t grid = 0;  // this frame's
};

}  // namespace sylva
