#include "systems/select_representation_system.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "ecs/parallel.h"
#include "lod/billboard_cloud_lod.h"
#include "lod/ladder.h"
#include "lod/point_line_lod.h"

namespace sylva {

namespace {

// The part number of a plant's dither for the budget's shared bucket (lod/rung_solver.h
// lambda_choice), apart from the dithers of its point and line counts.
constexpr std::uint32_t k_lambda_dither_part = 0x4c414d42;  // "LAMB"

// The rung index of `r` in a species' tables, or k_max_rungs when it has none.
std::uint8_t rung_index(const species_rung_tables& tables, representation r) {
    for (std::size_t i = 0; i < tables.rungs.size(); ++i)
        if (tables.rungs[i].rung == r) return std::uint8_t(i);
    return std::uint8_t(k_max_rungs);
}

// DESIGN §1.5 `auto`: every plant drawn (seen or casting) on the rung the budget solver picks
// (lod/rung_solver.h). Under a budget, two passes over the plants: each chunk's histogram of
// cost savings over λ, merged in chunk order; then each plant's choice at λ, with hysteresis,
// and its predicted cost summed per chunk (λ at least the gain, rung_budget::gain_per_us). Under
// an error threshold only the second pass, each plant on its cheapest rung within it; at a gain
// alone the same, each plant's choice at λ = the gain. A plant whose rung changed keeps the old
// one as a partner dissolving over fade_frames frames.
void choose_by_budget(ecs::system_context<select_representation_system>& ctx) {
    const camera& cam = ctx.single<camera>();
    const auto& library = ctx.resource<species_library>().species;
    rung_budget& budget = ctx.resource_mut<rung_budget>();
    auto plants = ctx.query<const world_transform, const bounds, const plant_instance, lod_state, fade_alpha>();
    const double pixel = image_plane_units(1.0, double(cam.fov_y), double(cam.viewport_height_px));
    const auto size_of = [&](const world_transform& t, const plant_instance& p) {
        const float distance = float(glm::length(t.position - cam.position));
        return projected_size_px(library[std::size_t(p.species)].bounding_radius * t.scale, distance, pixel) *
               cam.lod_scale;
    };
    // resources/seen_pixels.h: what the last frame showed of the plant, and with which rung. The
    // counts are by dense plant index, which is each_chunk's position only over aligned tables
    // (spawn_scenario aligns them); otherwise nothing is known and every plant is judged whole.
    const seen_pixels& seen = ctx.resource<seen_pixels>();
    const bool dense = plants.aligned();
    // A plant its eco tile drew last frame showed its pixels as the tile's: judged whole.
    const auto shown_of = [&](std::size_t plant, const species_rung_tables& tables, const lod_state& lod) {
        return dense && lod.current != representation::eco_tile
                   ? shown_last_frame{shown_pixels(seen, plant), rung_index(tables, lod.current)}
                   : shown_last_frame{};
    };
    // The eco-tile rung is not the solver's (lod/ladder.h): a plant on points goes on to its tile
    // by its size, as the ladder's last step says, and aggregate_eco_tiles decides whether the
    // tile draws it. To the solver a plant its tile drew was on points.
    const lod_policy& policy = ctx.resource<lod_policy>();
    const auto solver_rung = [](representation r) {
        return r == representation::eco_tile ? representation::points : r;
    };
    // Nor is the shell rung (Behrendt 2005 §3.3 end): the shell is the terrain's one layer, fading
    // in by distance the same for every plant (resources/shell_view.h), not a rung with a cost per
    // plant. A plant whose ladder ends in it is the shell's beyond the shell's band (no choice, no
    // cost); in the band's far half it draws the solver's choice as the shell's partner, fading
    // out as 2(1 − shell fade), and nearer the solver's choice whole (lod/ladder.h
    // choose_rung_with_shell, as by size). There the partner slot is the handover's, so a plant
    // keeps the rung it came with (a change would swap at the partner's opacity, undissolved),
    // and the budget counts that rung as fixed.
    const shell_view* shells = ctx.try_resource<shell_view>();
    const auto shell_fade_of = [&](const world_transform& t, const plant_instance& p) {
        const ladder& l = policy.ladders[std::size_t(p.species)];
        if (!shells || l.count < 2 || l.rungs[l.count - 1] != representation::shell) return 0.0f;
        return shell_fade_at(*shells, float(glm::length(t.position - cam.position)));
    };
    // The plant's rung last frame: in the shell's band, the shell's partner. After a cut
    // (rung_budget::cut) none was shown: nothing to hold (hysteresis, the shell's band) or
    // dissolve.
    const auto rung_before = [&](const lod_state& lod, const fade_alpha& fade) {
        if (budget.cut) return representation::none;
        return solver_rung(lod.current == representation::shell ? fade.partner : lod.current);
    };
    // The rung (an index) a plant in the far half of the shell's band holds, k_max_rungs for none.
    const auto held_in_band = [&](float shell_fade, const species_rung_tables& tables, representation was) {
        return shell_fade >= 0.5f ? rung_index(tables, was) : std::uint8_t(k_max_rungs);
    };
    // What a plant's shadow costs depends on the cascade it falls in, not on its size on screen:
    // the tables measured it at their views' cascade, and a plant near the camera but out of view
    // (or in a frame whose nearest cascade shades nothing) casts into a coarser one, or none. On
    // `valley` costed as in the tables, 2,460 plants only casting were predicted at 238 ms
    // when the whole shadow pass took 26. A plant is drawn into every cascade its sphere
    // overlaps (build_draw_list); its cost is taken at the finest, which has most fragments.
    const cascade_set& cascades = ctx.resource<cascade_set>();
    const std::array<cascade_bounds, k_max_cascades> boxes = cascade_boxes(cascades);
    // The texel of the finest cascade the plant casts into, 0 when it casts into none.
    const auto caster_texel_of = [&](const world_transform& t, const bounds& b, const lod_state& lod) {
        if (!lod.in_shadow_range) return 0.0f;
        const glm::vec3 center = glm::vec3(t.position - cam.position) + glm::vec3(0.0f, b.center_height, 0.0f);
        for (int k = 0; k < cascades.count; ++k)
            if (sphere_overlaps_cascade(boxes[std::size_t(k)], center, b.radius))
                return cascades.texel_world_size[std::size_t(k)];
        return 0.0f;
    };
    // Per-chunk results folded in chunk order: the same sums for any thread count.
    const std::size_t chunks = ecs::chunk_count(plants.size(), ctx.chunk());
    budget.histograms.assign(chunks, lambda_histogram{});
    budget.costs.assign(chunks, 0.0);
    const bool by_error = budget.max_error > 0.0;
    // At a fixed gain alone (no budget to hold, no target to adapt it to) λ is the gain: no
    // histogram, each plant judged once, in the choosing pass, as under an error threshold.
    const bool one_pass =
        by_error || (budget.gain_per_us > 0.0 && !(budget.plant_budget_us > 0.0) &&
                     !(budget.target_frame_ms > 0.0));
    budget.offers.resize(std::max(budget.offers.size(), chunks));
    for (std::size_t k = 0; k < chunks; ++k) budget.offers[k].clear();
    // The per-plant work of both passes is out of line (noinline): only the plants seen or
    // casting reach it, 18,000 of frame_update_bench's million, and inlined it made the walk
    // over every plant a call that saved and restored six registers per plant: the solver took
    // 3.3 ms on 2 threads, 1.9 ms out of line (choosing by size: 0.6 ms).
    const auto offer = [&](std::size_t i, const world_transform& t, const bounds& b, const plant_instance& p,
                           const lod_state& lod, const fade_alpha& fade, std::size_t chunk) __attribute__((noinline)) {
        const float shell_fade = shell_fade_of(t, p);
        if (!(shell_fade < 1.0f)) return;  // the shell's: no choice, no cost
        const species_rung_tables& tables = budget.tables[std::size_t(p.species)];
        const float texel = caster_texel_of(t, b, lod);
        rung_candidates c = candidates_at(tables, size_of(t, p), lod.visible, texel > 0.0f, shown_of(i, tables, lod), texel);
        budget.offers[chunk].push_back(c);
        if (const std::uint8_t held = held_in_band(shell_fade, tables, rung_before(lod, fade)); held < c.count)
            c = {{c.error[held]}, {c.cost_us[held]}, c.plant_pixels, 1};  // no choice: no saving to offer
        budget.histograms[chunk].add(c);
    };
    if (!one_pass) {
        ctx.parallel_for(plants.size(), [&](std::size_t begin, std::size_t end, std::size_t chunk) {
            std::size_t plant = begin;  // the dense index each_chunk walks
            plants.each_chunk(begin, end, [&](ecs::entity, const world_transform& t, const bounds& b,
                                              const plant_instance& p, lod_state& lod, fade_alpha& fade) {
                const std::size_t i = plant++;
                if (lod.visible || lod.in_shadow_range) offer(i, t, b, p, lod, fade, chunk);
            });
        });
    }
    lambda_histogram total;
    for (const lambda_histogram& h : budget.histograms) total.merge(h);
    const lambda_choice lambda =
        one_pass ? lambda_choice{} : solve_lambda(total, budget.plant_budget_us);
    budget.lambda = std::max(lambda.at, budget.gain_per_us);
    budget.most_useful_us = total.cost_at_zero_us;
    budget.least_possible_us = total.cheapest_cost_us();
    const float fade_step = 1.0f / float(std::max<std::uint32_t>(budget.fade_frames, 1));
    // A seen or casting plant's rung (its lod_state and fade written), and its predicted cost;
    // under a budget its candidates are the next of its chunk's offers (the same plants in the
    // same order: both passes skip the same ones), under an error threshold judged here.
    const auto choose = [&](std::size_t i, const world_transform& t, const bounds& b, const plant_instance& p,
                            lod_state& lod, fade_alpha& fade, const rung_candidates*& offered) __attribute__((noinline)) {
        const float shell_fade = shell_fade_of(t, p);
        if (!(shell_fade < 1.0f)) {
            lod.current = representation::shell;
            fade = {};
            return 0.0;  // the shell's: no cost
        }
        const species_rung_tables& tables = budget.tables[std::size_t(p.species)];
        const float size = size_of(t, p);
        const float texel = one_pass ? caster_texel_of(t, b, lod) : 0.0f;
        const rung_candidates c = one_pass ? candidates_at(tables, size, lod.visible, texel > 0.0f,
                                                           shown_of(i, tables, lod), texel)
                                           : *offered++;
        if (budget.cut) fade = {};  // nothing dissolves from a rung never shown
        const representation was = rung_before(lod, fade);
        const std::uint8_t previous = rung_index(tables, was);
        const std::uint8_t held = held_in_band(shell_fade, tables, was);
        // Only under a budget does a plant need its dither (the hash is per plant, per frame).
        const std::uint8_t chosen =
            held < c.count ? held
            : by_error
                ? cheapest_within(c, budget.max_error * double(c.plant_pixels), previous,
                                  budget.hysteresis)
                : choose_at(c,
                            std::max(budget.gain_per_us,
                                     lambda.for_plant(sample_dither(p.seed, k_lambda_dither_part),
                                                      budget.hysteresis)),
                            previous, budget.hysteresis);
        const double chosen_cost = double(c.cost_us[chosen]);
        const representation rung = tables.rungs[chosen].rung;
        if (fade.partner == representation::eco_tile || (was == representation::points && fade.partner == representation::points))
            fade = {};  // last frame's eco-tile band, not a dissolve
        if (rung != was && was != representation::none) {
            fade = {1.0f, was};  // the old rung dissolves; the new one is whole
        } else if (fade.partner != representation::none) {
            fade.value -= fade_step;
            if (!(fade.value > 0.0f) || fade.partner == rung) fade = {};
        }
        lod.current = rung;
        if (rung == representation::points && fade.partner == representation::none) {
            const ladder& l = policy.ladders[std::size_t(p.species)];
            if (l.count > 0 && l.rungs[l.count - 1] == representation::eco_tile) {
                const ladder_choice step = choose_rung(l, size);
                if (eco_tile_share(step.primary, step.partner, step.partner_fade) > 0.0f) {
                    lod.current = step.primary;
                    fade = {step.partner_fade, step.partner};
                }
            }
        }
        if (shell_fade >= 0.5f) {
            fade = {2.0f * (1.0f - shell_fade), lod.current};
            lod.current = representation::shell;
        }
        if (!lod.visible) fade = {};  // only a seen plant draws a partner
        return chosen_cost;
    };
    ctx.parallel_for(plants.size(), [&](std::size_t begin, std::size_t end, std::size_t chunk) {
        double& cost = budget.costs[chunk];
        const rung_candidates* offered = budget.offers[chunk].data();
        std::size_t plant = begin;
        plants.each_chunk(begin, end, [&](ecs::entity, const world_transform& t, const bounds& b,
                                          const plant_instance& p, lod_state& lod, fade_alpha& fade) {
            const std::size_t i = plant++;
            lod.previous = lod.current;
            if (lod.visible || lod.in_shadow_range) {
                cost += choose(i, t, b, p, lod, fade, offered);
                return;
            }
            lod.current = representation::none;
            fade = {};
        });
    });
    budget.predicted_us = 0.0;
    for (const double cost : budget.costs) budget.predicted_us += cost;
    budget.cut = false;
}

}  // namespace

void select_representation_system::run(ecs::system_context<select_representation_system>& ctx) {
    const lod_policy& policy = ctx.resource<lod_policy>();
    if (policy.mode == lod_policy::kind::ladder && ctx.resource<rung_budget>().active()) {
        choose_by_budget(ctx);
        return;
    }
    const camera& cam = ctx.single<camera>();
    const auto& library = ctx.resource<species_library>().species;
    const double pixel = image_plane_units(1.0, double(cam.fov_y), double(cam.viewport_height_px));
    const shell_view* shells = ctx.try_resource<shell_view>();  // none: a world without shells
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
                const float size = projected_size_px(species.bounding_radius * t.scale, distance, pixel) *
                                   cam.lod_scale * policy.ladder_size_scale;
                choice = choose_rung_with_shell(policy.ladders[static_cast<std::size_t>(p.species)], size,
                                                shells ? shell_fade_at(*shells, distance) : 0.0f);
            } else if (policy.mode == lod_policy::kind::billboard_clouds) {
                choice = choose_cloud_lod(species, policy.cloud_distance_m, distance, t.scale, cam.lod_scale);
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
