#pragma once
// How far the ground's coarser grids may stray on screen (components/ground_tile.h): the
// scenario's terrain.max_error_px, set at spawn; read by select_ground_grid.
namespace sylva {

// Half a pixel by default: the coarser ground stays within the reference's own sampling (the
// bench's reference draws every sample).
inline constexpr float k_ground_error_px = 0.5f;

struct ground_lod {
    float max_error_px = k_ground_error_px;  // 0: every tile on the terrain's own samples
};

}  // namespace sylva
