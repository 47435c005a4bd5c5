#include "systems/update_lodf_system.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "ecs/parallel.h"
#include "lod/lodf.h"
#include "lod/point_line_lod.h"
#include "models/cache/bake_cache.h"

namespace sylva {

std::uint32_t lodf_leaves_at(std::uint32_t leaves, std::uint32_t clusters, float size_px, float top_px) {
    if (!(top_px > 0.0f) || !(size_px < top_px)) return leaves;
    const double share = std::max(double(size_px), 0.0) / double(top_px);
    const auto n = std::uint32_t(std::lround(double(leaves) * share * share));
    return std::clamp(n, std::min(clusters, leaves), leaves);
}

float lodf_top_px(const ladder& l) {
    for (std::size_t i = 1; i < l.count; ++i)
        if (l.rungs[i] == representation::lodf) return l.below_px[i] * (1.0f + l.band[i]);
    return 0.0f;
}

std::uint64_t lodf_state_hash(const lodf_slots& slots, std::span<const cluster_changes> clusters, std::uint64_t seed) {
    const auto add = [&seed](const auto& value) { seed = hash_bytes(std::as_bytes(std::span(&value, 1)), seed); };
    for (const lodf_slot& slot : slots.slots) {
        add(slot.plant);
        add(slot.species);
        add(slot.init_position);
        add(slot.leaves);
        add(slot.taken);
    }
    add(slots.overflow);
    add(slots.changed_clusters);
    for (const std::vector<std::uint32_t>& changed : slots.changed)
        seed = hash_bytes(std::as_bytes(std::span(changed)), seed);
    return hash_bytes(std::as_bytes(clusters), seed);  // cluster_changes: three u32, no padding
}

void update_lodf_system::run(ecs::system_context<update_lodf_system>& ctx) {
    const lod_policy& policy = ctx.resource<lod_policy>();
    lodf_slots& state = ctx.resource_mut<lodf_slots>();
    state.overflow = 0;
    state.changed_clusters = 0;
    if (state.slots.empty()) return;  // nothing to do costs nothing
    const species_library& library = ctx.resource<species_library>();
    const auto lods = ctx.read<lod_state>().data();
    const auto fades = ctx.read<fade_alpha>().data();
    const auto transforms = ctx.read<world_transform>().data();
    const auto plants = ctx.read<plant_instance>().data();
    const std::size_t n = ctx.read<lod_state>().size();
    const auto on_rung = [&](std::size_t i) {
        return lods[i].current == representation::lodf ||
               (fades[i].partner == representation::lodf && fades[i].value > 0.0f);
    };
    // Slots first: a plant that left the rung frees its slot; a plant new on it takes the lowest
    // free one, in plant order, so the assignment is the same for any thread count.
    state.slot_of_plant.resize(n, k_no_lodf_slot);
    for (lodf_slot& slot : state.slots) {
        slot.taken = 0;
        if (slot.plant != k_no_lodf_slot && (slot.plant >= n || !on_rung(slot.plant))) {
            if (slot.plant < n) state.slot_of_plant[slot.plant] = k_no_lodf_slot;
            slot = {};
        }
    }
    std::size_t free_slot = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!on_rung(i) || state.slot_of_plant[i] != k_no_lodf_slot) continue;
        const auto species = std::uint32_t(plants[i].species);
        if (species >= library.lodf.size() || library.species[species].lodf_clusters == 0) continue;
        while (free_slot < state.slots.size() && state.slots[free_slot].plant != k_no_lodf_slot) ++free_slot;
        if (free_slot == state.slots.size()) {
            ++state.overflow;
            continue;
        }
        state.slots[free_slot] = {std::uint32_t(i), species, 0, library.species[species].lodf_leaves, 1};
        state.slot_of_plant[i] = std::uint32_t(free_slot);
    }
    // Then each slot's detail, slots in parallel: its own range of cluster entities.
    const camera& cam = ctx.single<camera>();
    const double pixel = image_plane_units(1.0, double(cam.fov_y), double(cam.viewport_height_px));
    cluster_changes* clusters = ctx.write<cluster_changes>().data();
    ctx.parallel_for(state.slots.size(), 1, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t s = begin; s < end; ++s) {
            lodf_slot& slot = state.slots[s];
            std::vector<std::uint32_t>& changed = state.changed[s];
            changed.clear();
            if (slot.plant == k_no_lodf_slot) continue;
            const species_entry& species = library.species[slot.species];
            const lodf_structure& lodf = library.lodf[slot.species];
            const std::span<cluster_changes> mine(clusters + s * state.clusters_per_slot, lodf.clusters.size());
            if (slot.taken) {
                reset_lodf_clusters(lodf, mine);
                slot.init_position = 0;
            }
            const world_transform& t = transforms[slot.plant];
            const float distance = float(glm::length(t.position - cam.position));
            const float size = projected_size_px(species.bounding_radius * t.scale, distance, pixel) * cam.lod_scale *
                               policy.ladder_size_scale;
            const float top = slot.species < policy.ladders.size() ? lodf_top_px(policy.ladders[slot.species]) : 0.0f;
            slot.leaves = lodf_leaves_at(species.lodf_leaves, species.lodf_clusters, size, top);
            retarget_lodf(lodf, mine, slot.init_position, collapses_for_leaves(lodf, slot.leaves), changed);
        }
    });
    for (const std::vector<std::uint32_t>& c : state.changed) state.changed_clusters += std::uint32_t(c.size());
}

}  // namespace sylva
