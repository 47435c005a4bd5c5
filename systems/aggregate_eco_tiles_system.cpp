#include "systems/aggregate_eco_tiles_system.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "ecs/parallel.h"
#include "lighting/fog.h"
#include "lod/eco_tiles.h"
#include "lod/ladder.h"

namespace sylva {

double tile_prefixes(const tile_point_sets& sets, std::uint32_t tile, double distance_m,
                     double sample_distance, double splat_factor, std::vector<std::uint32_t>& counts,
                     std::vector<std::uint8_t>& splats, double fog_density_per_m) {
    const double splat_distance =
        fog_sample_distance(sample_distance, distance_m, fog_density_per_m);
    double share = 1.0;
    for (std::uint32_t i = sets.first_part[tile]; i < sets.first_part[tile + 1]; ++i) {
        const tile_point_part& part = sets.parts[i];
        if (part.primitive == lod_primitive::points) {
            // Deussen 2002 Eq. 1 for the whole tile: its plants' area at the tile's distance.
            const double p =
                required_points(part.area_m2, distance_m, splat_distance, splat_factor);
            if (!(p >= 0.0)) return 0.0;
            if (p > double(part.count)) share = std::min(share, double(part.count) / p);
            counts[i] = std::uint32_t(std::min(p, double(part.count)));
            splats[i] = 0;
        } else {
            // Eq. 2: q = A'_l / A'_sl with l the length of all the tile's lines; q·n_l of the
            // n_l lines the set stands for, which the set must hold.
            primitive_costs lines_always;  // a tile set has no triangles to fall back on
            lines_always.line = 0.0;
            // Short lines become splats at their ends, two per line the set holds.
            const part_draw d =
                select_lines_fogged(part.area_m2, part.line_length_m, part.line_error_m,
                                    part.stands_for, part.stands_for, distance_m, sample_distance,
                                    splat_distance, lines_always, 1.0, splat_factor);
            if (d.triangles > 0) return 0.0;  // lines as wide as polygons: no set can draw them
            const std::uint32_t held = d.splats ? 2 * part.count : part.count;
            if (d.primitives > held) share = std::min(share, double(held) / double(d.primitives));
            counts[i] = std::min(d.primitives, held);
            splats[i] = d.splats ? 1 : 0;
        }
    }
    return share;
}

double tile_distance_share(double distance_m, double radius_m, double shadow_distance_m) {
    const double near = k_aggregate_distance_factor * radius_m;
    if (!(distance_m - radius_m > shadow_distance_m) || !(distance_m > near)) return 0.0;
    return std::min(1.0, (distance_m - near) / (k_aggregate_ramp * near));
}

namespace {

// What a plant lets its tile draw of it under a ladder (0 .. 1): its last-step share. A culled
// plant does not hold its tile back (the tile's set draws it with the rest where it is seen).
float share_of(const lod_state& lod, const fade_alpha& fade) {
    if (lod.current == representation::none) return 1.0f;
    return eco_tile_share(lod.current, fade.partner, fade.value);
}

// The plants of a tile drawn `share` (> 0) by its sets: on the eco-tile rung, the rest of each
// seen plant drawn by its own prefixes as the points partner.
void hand_to_tile(lod_state* lods, fade_alpha* fades, std::uint32_t first, std::uint32_t end, float share) {
    for (std::uint32_t k = first; k < end; ++k) {
        lod_state& lod = lods[k];
        if (lod.current == representation::none) continue;
        lod.current = representation::eco_tile;
        fades[k] = share < 1.0f && lod.visible ? fade_alpha{1.0f - share, representation::points} : fade_alpha{};
    }
}

// The plants of a range no tile draws: a plant the ladder handed to its tile is points after all,
// whole (the rung before, ladder.h), and a points plant keeps no eco-tile partner.
void keep_as_plants(lod_state* lods, fade_alpha* fades, std::size_t first, std::size_t end) {
    for (std::size_t k = first; k < end; ++k) {
        if (lods[k].current == representation::eco_tile) {
            lods[k].current = representation::points;
            fades[k] = {};
        } else if (fades[k].partner == representation::eco_tile) {
            fades[k] = {};
        }
    }
}

}  // namespace

void aggregate_eco_tiles_system::run(ecs::system_context<aggregate_eco_tiles_system>& ctx) {
    tile_point_draws& draws = ctx.resource_mut<tile_point_draws>();
    const tile_point_sets& sets = ctx.resource<tile_point_sets>();
    draws.counts.assign(sets.parts.size(), 0);
    draws.splats.assign(sets.parts.size(), 0);
    draws.tiles = draws.plants = 0;
    const lod_policy& policy = ctx.resource<lod_policy>();
    const bool points_policy = policy.mode == lod_policy::kind::points_lines;
    const bool ladder_reaches = policy.any_ladder_reaches(representation::eco_tile);
    if (!(points_policy && policy.tile_sets) && !ladder_reaches) return;
    auto& lods = ctx.write<lod_state>();
    auto& fades = ctx.write<fade_alpha>();
    lod_state* lod = lods.data();
    fade_alpha* fade = fades.data();
    const std::size_t plants = std::min(lods.size(), fades.size());
    const auto& tiles = ctx.read<tile>();
    // Without tile sets no plant is drawn by its tile.
    if (sets.parts.empty() || tiles.size() == 0) {
        if (ladder_reaches)
            ctx.parallel_for(plants, [&](std::size_t begin, std::size_t end, std::size_t) {
                keep_as_plants(lod, fade, begin, end);
            });
        return;
    }
    const camera& cam = ctx.single<camera>();
    const double d = image_plane_units(policy.points.sample_distance_px, cam.fov_y, cam.viewport_height_px);
    const double fog = policy.points.fog_weighted ? k_fog_density_per_m : 0.0;
    const shadow_settings& shadows = ctx.resource<shadow_settings>();
    const double shadow_distance = shadows.cascades > 0 ? double(shadows.max_distance_m) : 0.0;
    const auto& visibility = ctx.read<tile_visibility>();

    // 1. What each tile's plants let it draw: the least share of any of them (leaves in parallel,
    //    then up the tree: in preorder a tile's children come after it). Under the point/line
    //    policy every drawn plant is points and lets it all: no pass over the plants.
    std::vector<float>& allowed = draws.allowed;
    allowed.assign(tiles.size(), 1.0f);
    if (!points_policy) ctx.parallel_for(tiles.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t i = begin; i < end; ++i) {
            const tile& t = tiles.data()[i];
            if (!t.is_leaf()) continue;
            float least = 1.0f;
            for (std::uint32_t k = t.first_plant; k < t.first_plant + t.plant_count && k < plants; ++k)
                least = std::min(least, share_of(lod[k], fade[k]));
            allowed[i] = least;
        }
    });
    for (std::size_t i = tiles.size(); i-- > 0;) {
        const ecs::entity parent = tiles.data()[i].parent;
        if (parent.is_null()) continue;
        float& up = allowed[tiles.index_of(parent)];
        up = std::min(up, allowed[i]);
    }

    // 2. From the roots down: the first visible tile that draws its sets draws them at its share,
    //    and its subtree no more; every leaf no tile covers keeps its plants. Serial:
    //    a few hundred tiles, and the order of the writes is then fixed.
    std::vector<float>& drawn = draws.share;
    drawn.assign(tiles.size(), 0.0f);  // per tile: the share of its sets drawn
    std::vector<std::uint32_t>& covering = draws.covering;
    covering.assign(tiles.size(), k_no_eco_tile);
    std::uint32_t covered_end = 0;
    for (std::size_t i = 0; i < tiles.size();) {
        const tile& t = tiles.data()[i];
        covered_end = std::max(covered_end, t.first_plant + t.plant_count);
        std::size_t next = i + 1;
        while (next < tiles.size() && tiles.data()[next].depth > t.depth) ++next;  // end of subtree
        double share = 0.0;
        if (t.plant_count == 0) {  // nothing to draw, here or below
            i = next;
            continue;
        }
        if (visibility.data()[i].visible && allowed[i] > 0.0f) {
            const double r = glm::length(sets.origin[i] - cam.position);
            share = std::min({double(allowed[i]), tile_distance_share(r, double(sets.radius[i]), shadow_distance)});
            if (share > 0.0)
                share = std::min(share, tile_prefixes(sets, std::uint32_t(i), r, d, policy.points.splat_factor,
                                                      draws.counts, draws.splats, fog));
        }
        // A tile draws its sets whole, or a leaf draws them in part; an inner tile that cannot draw
        // all of itself leaves it to its children (their sets hold 4 times the samples, and a
        // plant in the band holds back only its own leaf). Parent and children draw the same
        // density, so going over from one to the other changes no plant.
        if (!(share >= 1.0 || (t.is_leaf() && share > 0.0))) {
            for (std::uint32_t p = sets.first_part[i]; p < sets.first_part[i + 1]; ++p) draws.counts[p] = 0;
            i = visibility.data()[i].visible ? i + 1 : next;  // a culled tile's plants are culled too
            continue;
        }
        // Deussen 2002 §5.3's blend: the sets draw `share` of their prefixes, the plants the rest.
        for (std::uint32_t p = sets.first_part[i]; p < sets.first_part[i + 1]; ++p)
            draws.counts[p] = std::uint32_t(double(draws.counts[p]) * share + 0.5);
        for (std::size_t j = i; j < next; ++j) covering[j] = std::uint32_t(i);
        drawn[i] = float(share);
        ++draws.tiles;
        draws.plants += t.plant_count;
        i = next;
    }

    // 3. The plants, by the tile that covers them (leaf ranges are disjoint: in parallel).
    ctx.parallel_for(tiles.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t i = begin; i < end; ++i) {
            const tile& t = tiles.data()[i];
            const std::uint32_t by = covering[i];
            if (by == std::uint32_t(i)) {  // the covering tile hands over its whole range
                const std::uint32_t end_plant = std::min<std::uint32_t>(t.first_plant + t.plant_count, std::uint32_t(plants));
                hand_to_tile(lod, fade, t.first_plant, end_plant, drawn[i]);
            } else if (by == k_no_eco_tile && t.is_leaf() && ladder_reaches) {
                keep_as_plants(lod, fade, t.first_plant, std::min<std::size_t>(t.first_plant + t.plant_count, plants));
            }
        }
    });
    // Plants no tile holds (spawned outside the tree).
    if (ladder_reaches && covered_end < plants)
        ctx.parallel_for(plants - covered_end, [&](std::size_t begin, std::size_t end, std::size_t) {
            keep_as_plants(lod, fade, covered_end + begin, covered_end + end);
        });
}

}  // namespace sylva

