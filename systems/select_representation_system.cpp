#include "systems/select_representation_system.h"

#include <glm/geometric.hpp>

#include "ecs/parallel.h"

namespace sylva {

representation choose_representation(const species_entry& species, float distance_m, float scale,
                                      float lod_scale) {
    const float factor = scale * lod_scale;
    if (distance_m < species.reduced_distance_m * factor) return representation::mesh_full;
    if (distance_m < species.far_distance_m * factor) return representation::mesh_reduced;
    return representation::mesh_far;
}

representation choose_representation(const lod_policy& policy, const species_entry& species, float distance_m,
                                     float scale, float lod_scale) {
    switch (policy.mode) {
        case lod_policy::kind::single: return policy.near;
        // The point/line representation covers every distance: its prefixes shrink with the
        // projected size (update_point_prefix), down to polygons near and a few points far.
        case lod_policy::kind::points_lines: return representation::points;
        case lod_policy::kind::hard_switch:
            // A NaN distance compares false and so takes the far side, like the distance levels.
            return distance_m < policy.switch_distance_m * scale * lod_scale ? policy.near : policy.far;
        case lod_policy::kind::distance_levels: break;
    }
    return choose_representation(species, distance_m, scale, lod_scale);
}

void select_representation_system::run(ecs::system_context<select_representation_system>& ctx) {
    const camera& cam = ctx.single<camera>();
    const auto& library = ctx.resource<species_library>().species;
    const lod_policy& policy = ctx.resource<lod_policy>();
    auto plants = ctx.query<const world_transform, const plant_instance, lod_state>();
    ctx.parallel_for(plants.size(), ecs::k_default_chunk, [&](std::size_t begin, std::size_t end, std::size_t) {
        plants.each_chunk(begin, end, [&](ecs::entity, const world_transform& t, const plant_instance& p,
                                          lod_state& lod) {
            lod.previous = lod.current;
            if (!lod.visible && !lod.in_shadow_range) {
                lod.current = representation::none;
                return;
            }
            const float distance = float(glm::length(t.position - cam.position));
            lod.current = choose_representation(policy, library[static_cast<std::size_t>(p.species)], distance,
                                                t.scale, cam.lod_scale);
        });
    });
}

}  // namespace sylva
