#pragma once
// Every ground tile's grid this frame (lod/ground_grid.h): the coarsest whose vertical error,
// seen from the camera at the tile's nearest point, shows as at most ground_lod::max_error_px,
// tiles in parallel; grid 0 everywhere for full-geometry cameras (the bench's reference). Nothing
// when the scene spawned no ground tiles (scenes built by hand draw the terrain's own tiles).
#include "components/camera.h"
#include "components/ground_tile.h"
#include "ecs/system.h"
#include "resources/ground_lod.h"

namespace sylva {

struct select_ground_grid_system {
    static constexpr std::string_view k_name = "select_ground_grid";
    static constexpr ecs::phase k_phase = ecs::phase::cull;
    using reads = ecs::reads<camera, ground_lod>;
    using writes = ecs::writes<ground_tile>;
    static void run(ecs::system_context<select_ground_grid_system>& ctx);
};

}  // namespace sylva
