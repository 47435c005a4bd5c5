#pragma once
// Rebollo 2006 §3.3 for every plant on the LoDF rung (or fading to or from it): its slot
// (resources/lodf_slots.h), and its foliage's detail from its projected size: the leaves its
// species has at the size where the rung takes over, falling with the plant's projected area,
// L·(size / S_top)², down to one per cluster. The walk over Changed_group then updates the
// slot's cluster entities (Eq. 10–13), slots in parallel chunks.
#include <span>

#include "components/camera.h"
#include "components/cluster_changes.h"
#include "components/fade_alpha.h"
#include "components/lod_state.h"
#include "components/plant_instance.h"
#include "components/transform.h"
#include "ecs/system.h"
#include "lod/ladder.h"
#include "resources/lod_policy.h"
#include "resources/lodf_slots.h"
#include "resources/scene_assets.h"

namespace sylva {

// The leaves a plant of `leaves` (L) leaves and `clusters` (G) clusters draws at projected size
// `size_px` on a ladder whose LoDF rung takes over below `top_px`: L·(size / top)², within
// [G, L]. top_px <= 0 (LoDF the nearest rung): L above any size.
std::uint32_t lodf_leaves_at(std::uint32_t leaves, std::uint32_t clusters, float size_px, float top_px);

// The projected size below which the ladder's LoDF rung is whole: the upper edge of the band
// into it; 0 when LoDF is the nearest rung or the ladder has none.
float lodf_top_px(const ladder& l);

// FNV-1a 64 of what update_lodf writes: the slots (field by field: lodf_slot has padding) and
// every cluster entity's counters, chained from `seed`. Equal for any thread count (the
// determinism tests and the player's state hash compare it).
std::uint64_t lodf_state_hash(const lodf_slots& slots, std::span<const cluster_changes> clusters, std::uint64_t seed);

struct update_lodf_system {
    static constexpr std::string_view k_name = "update_lodf";
    static constexpr ecs::phase k_phase = ecs::phase::transition;
    using reads = ecs::reads<camera, world_transform, plant_instance, lod_state, fade_alpha, species_library, lod_policy>;
    using writes = ecs::writes<cluster_changes, lodf_slots>;
    static void run(ecs::system_context<update_lodf_system>& ctx);
};

}  // namespace sylva
