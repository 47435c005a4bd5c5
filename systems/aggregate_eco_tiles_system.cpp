#include "systems/aggregate_eco_tiles_system.h"

#include <glm/geometric.hpp>

#include "lighting/fog.h"

namespace sylva {

bool tile_prefixes(const tile_point_sets& sets, std::uint32_t tile, double distance_m,
                   double sample_distance, double splat_factor, std::vector<std::uint32_t>& counts,
                   std::vector<std::uint8_t>& splats, double fog_density_per_m) {
    const double splat_distance =
        fog_sample_distance(sample_distance, distance_m, fog_density_per_m);
    for (std::uint32_t i = sets.first_part[tile]; i < sets.first_part[tile + 1]; ++i) {
        const tile_point_part& part = sets.parts[i];
        if (part.primitive == lod_primitive::points) {
            // Deussen 2002 Eq. 1 for the whole tile: its plants' area at the tile's distance.
            const double p =
                required_points(part.area_m2, distance_m, splat_distance, splat_factor);
            if (!(p <= double(part.count))) return false;
            counts[i] = std::uint32_t(p);
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
            if (d.triangles > 0 || d.primitives > (d.splats ? 2 * part.count : part.count)) return false;
            counts[i] = d.primitives;
            splats[i] = d.splats ? 1 : 0;
        }
    }
    return true;
}

void aggregate_eco_tiles_system::run(ecs::system_context<aggregate_eco_tiles_system>& ctx) {
    tile_point_draws& draws = ctx.resource_mut<tile_point_draws>();
    const tile_point_sets& sets = ctx.resource<tile_point_sets>();
    draws.counts.assign(sets.parts.size(), 0);
    draws.splats.assign(sets.parts.size(), 0);
    draws.tiles = draws.plants = 0;
    const lod_policy& policy = ctx.resource<lod_policy>();
    if (sets.parts.empty() || policy.mode != lod_policy::kind::points_lines || !policy.tile_sets) return;
    const camera& cam = ctx.single<camera>();
    const double d = image_plane_units(policy.points.sample_distance_px, cam.fov_y, cam.viewport_height_px);
    const double fog = policy.points.fog_weighted ? k_fog_density_per_m : 0.0;
    const shadow_settings& shadows = ctx.resource<shadow_settings>();
    const double shadow_distance = shadows.cascades > 0 ? double(shadows.max_distance_m) : 0.0;
    const auto& tiles = ctx.read<tile>();
    const auto& visibility = ctx.read<tile_visibility>();
    auto& lods = ctx.write<lod_state>();
    // Preorder: a tile's subtree is the run of tiles after it that are deeper. Serial: a few
    // hundred tiles, and the order of the writes is then fixed.
    for (std::size_t i = 0; i < tiles.size();) {
        const tile& t = tiles.data()[i];
        std::size_t next = i + 1;
        while (next < tiles.size() && tiles.data()[next].depth > t.depth) ++next;  // end of subtree
        const double r = glm::length(sets.origin[i] - cam.position);
        const double radius = double(sets.radius[i]);
        const bool far = r >= k_aggregate_distance_factor * radius && r - radius > shadow_distance;
        if (!visibility.data()[i].visible || !far ||
            !tile_prefixes(sets, std::uint32_t(i), r, d, policy.points.splat_factor, draws.counts,
                           draws.splats, fog)) {
            for (std::uint32_t p = sets.first_part[i]; p < sets.first_part[i + 1]; ++p) draws.counts[p] = 0;
            if (!visibility.data()[i].visible) i = next;  // culled with its subtree
            else ++i;                                      // try the children
            continue;
        }
        // Drawn as its sets: none of its plants is drawn on its own.
        for (std::uint32_t k = t.first_plant; k < t.first_plant + t.plant_count; ++k) {
            lod_state& lod = lods.data()[k];
            lod.current = representation::none;
        }
        ++draws.tiles;
        draws.plants += t.plant_count;
        i = next;
    }
}

}  // namespace sylva
