#include "systems/select_representation_system.h"

#include <glm/geometric.hpp>

#include "ecs/parallel.h"
#include "lod/billboard_cloud_lod.h"
#include "lod/ladder.h"

namespace sylva {

void select_representation_system::run(ecs::system_context<select_representation_system>& ctx) {
    const camera& cam = ctx.single<camera>();
    const auto& library = ctx.resource<species_library>().species;
    const lod_policy& policy = ctx.resource<lod_policy>();
    auto plants = ctx.query<const world_transform, const plant_instance, lod_state, fade_alpha>();
    ctx.parallel_for(plants.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        plants.each_chunk(begin, end, [&](ecs::entity, const world_transform& t, const plant_instance& p,
                                          lod_state& lod, fade_alpha& fade) {
            lod.previous = lod.current;
            fade = {};
            if (!lod.visible && !lod.in_shadow_range) {
                lod.current = representation::none;
                return;
            }
            const float distance = float(glm::length(t.position - cam.position));
            const species_entry& species = library[static_cast<std::size_t>(p.species)];
            ladder_choice choice;
            if (policy.mode == lod_policy::kind::ladder) {
                // DESIGN §1.5: the rung by projected size; lod_scale stretches it as it does
                // every switch distance (the reference's 1e6 keeps every plant on its first rung).
                const float size = projected_size_px(species.bounding_radius * t.scale, distance, cam.fov_y,
                                                     cam.viewport_height_px) *
                                   cam.lod_scale * policy.ladder_size_scale;
                choice = choose_rung(policy.ladders[static_cast<std::size_t>(p.species)], size);
            } else if (policy.mode == lod_policy::kind::billboard_clouds) {
                const cloud_lod_choice c =
                    choose_cloud_lod(species, policy.cloud_distance_m, distance, t.scale, cam.lod_scale);
                choice = {c.primary, c.partner, c.partner_fade};
            } else {
                lod.current = choose_representation(policy, species, distance, t.scale, cam.lod_scale);
                return;
            }
            lod.current = choice.primary;
            // The partner is only seen, never casts (only the primary does): a plant merely in
            // shadow range has none.
            if (lod.visible && choice.partner != representation::none && choice.partner_fade > 0.0f)
                fade = {choice.partner_fade, choice.partner};
        });
    });
}

}  // namespace sylva
