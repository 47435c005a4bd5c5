#pragma once
// Turns the frame's LOD decisions into the draw list: one draw item per (visible plant, opaque
// pass) and per (shadow-casting plant, cascade it overlaps), keyed by pass, mesh and depth; a
// plant drawn as points and lines gives one item per non-empty prefix of its parts
// (point_prefix) in the view, and in each cascade the prefixes its texel size calls for
// (compute_shadow_prefix), each item carrying its prefix length; the octree cells of big plants
// (Deussen 2002 §6.1) add their own items, drawn with their plant's instance record; far eco
// tiles drawn as their point sets (§6.2) add one item per set, marked with k_tile_item_bit.
// During a billboard-cloud transition band (Behrendt 2005 §2.3, fade_alpha) a visible plant
// adds one more opaque item for its partner representation, marked with k_partner_item_bit,
// whose instance record carries the partner's fade; only the primary casts shadows.
// Items are counted and written in fixed-size chunks at offsets from a prefix sum, so the list
// is identical for any thread count; then radix-sorted, and runs of equal pass and mesh become
// instanced batches with their camera-relative instance records.
#include "components/population_ambient.h"
#include "components/bounds.h"
#include "components/cluster_changes.h"
#include "components/camera.h"
#include "components/fade_alpha.h"
#include "components/lod_state.h"
#include "components/octree_cell.h"
#include "components/plant_instance.h"
#include "components/point_prefix.h"
#include "components/transform.h"
#include "ecs/system.h"
#include "resources/draw_list.h"
#include "lighting/shadow_cascades.h"
#include "resources/lod_policy.h"
#include "resources/lodf_slots.h"
#include "systems/aggregate_eco_tiles_system.h"
#include "resources/scene_assets.h"

namespace sylva {


struct build_draw_list_system {
    static constexpr std::string_view k_name = "build_draw_list";
    static constexpr ecs::phase k_phase = ecs::phase::build;
    using reads = ecs::reads<camera, cluster_changes, lodf_slots, world_transform, bounds, plant_instance, lod_state, point_prefix, octree_cell,
                             cell_prefix, fade_alpha, species_library, cascade_set, lod_policy, primitive_costs,
                             tile_point_sets, tile_point_draws, population_ambient>;
    using writes = ecs::writes<draw_list>;
    static void run(ecs::system_context<build_draw_list_system>& ctx);
};

}  // namespace sylva
