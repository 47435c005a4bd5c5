#pragma once
// Chooses each visible plant's representation from its distance to the camera (scaled by the
// plant's size and the camera's lod_scale): the full mesh near, the reduced mesh beyond the
// species' reduced distance, the far mesh beyond its far distance. Under other policies: points
// and lines (Deussen 2002), billboard clouds with their transition bands (Behrendt 2005 §2.3,
// lod/billboard_cloud_lod.h), or each species' ladder by projected size (DESIGN §1.5,
// lod/ladder.h); for the last two it writes the band's partner and fade into fade_alpha. With
// measured rung tables (resources/rung_budget.h) a ladder's rung is instead the one the budget
// solver picks (lod/rung_solver.h), each plant's error weighed by the share of it the last
// frame showed (resources/seen_pixels.h), its shadow costed at the finest cascade it casts into
// (fit_shadow_cascades runs before), and a plant that changes rung dissolves its old one over a
// few frames. A ladder ending in the shell hands its plants over to it by the shell's fade
// distance (resources/shell_view.h, written by update_shells before this runs), by size and under
// the budget alike (there the shell's plants cost nothing and are no choice). Records the
// previous choice so measurements can count switches.
#include "components/bounds.h"
#include "components/camera.h"
#include "components/fade_alpha.h"
#include "components/lod_state.h"
#include "components/plant_instance.h"
#include "components/transform.h"
#include "ecs/system.h"
#include "lighting/shadow_cascades.h"
#include "lod/distance_lod.h"
#include "resources/lod_policy.h"
#include "resources/rung_budget.h"
#include "resources/scene_assets.h"
#include "resources/seen_pixels.h"
#include "resources/shell_view.h"

namespace sylva {

struct select_representation_system {
    static constexpr std::string_view k_name = "select_representation";
    static constexpr ecs::phase k_phase = ecs::phase::select;
    using reads = ecs::reads<camera, world_transform, bounds, plant_instance, species_library, lod_policy, seen_pixels,
                             shell_view, cascade_set>;
    using writes = ecs::writes<lod_state, fade_alpha, rung_budget>;
    static void run(ecs::system_context<select_representation_system>& ctx);
};

}  // namespace sylva
