#pragma once
// Behrendt 2005 §3.3: every shell tile's pyramid level and merge from the camera's distance to
// its nearest point (lod/shell_levels.h) and whether it touches the view frustum, tiles in
// parallel, and the shells' fade distances for this frame from the ladders' handover sizes
// (resources/shell_view.h), which select_representation reads to hand plants over to the shell
// by distance: it runs before it. Nothing when the scene has no shells.
#include "components/camera.h"
#include "components/shell_tile.h"
#include "ecs/system.h"
#include "resources/lod_policy.h"
#include "resources/scene_assets.h"
#include "resources/shell_view.h"

namespace sylva {

// The distance at which a plant of diameter `diameter_m` looks `size_px` high when one pixel is
// `pixel_units` on the image plane at distance 1 (lod/ladder.h projected_size_px, inverted).
float distance_for_size(float diameter_m, float size_px, double pixel_units);

struct update_shells_system {
    static constexpr std::string_view k_name = "update_shells";
    static constexpr ecs::phase k_phase = ecs::phase::cull;
    using reads = ecs::reads<camera, lod_policy, species_library>;
    using writes = ecs::writes<shell_tile, shell_view>;
    static void run(ecs::system_context<update_shells_system>& ctx);
};

}  // namespace sylva
