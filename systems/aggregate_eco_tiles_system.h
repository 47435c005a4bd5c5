#pragma once
// Deussen 2002 §6.2: "In distant views only this very sparse point representation is used.
// When zooming in, all the plants of the eco file are displayed." Walks the eco tiles from the
// roots, after selection: a visible tile whose plants all let it draw them is drawn as its sets'
// prefixes, and its plants are on the eco_tile rung (not drawn on their own); otherwise its
// children are tried, and the plants of leaf tiles no tile draws are drawn one by one.
//
// Which plants let their tile draw them: under the point/line policy every plant drawn as points;
// under a ladder, a plant in or beyond the step into its last rung, eco_tile_points (lod/ladder.h
// eco_tile_share), and a plant the tile does not draw falls back to points whole.
//
// The handover is Deussen 2002 §5.3's blend, not a switch: a tile draws a share s of its sets'
// prefixes and each of its seen plants the other 1 − s of its own prefixes (the points partner),
// both random subsets, so the density is the same throughout. s is the least of:
//   - its plants' shares (the nearest plant in the band holds the tile back);
//   - the distance ramp: 0 nearer than k_aggregate_distance_factor times the tile's radius (Eq. 1
//     at the tile's centre would be wrong for its near side), 1 from (1 + k_aggregate_ramp) times
//     that, linear between;
//   - what its sets hold: a set holding n of the p samples Eq. 1 or Eq. 2 asks for draws n / p.
// Only a leaf tile draws a share below 1; an inner tile that cannot draw all of itself leaves it
// to its children (the same density: going over between them changes no plant).
// Aggregated tiles cast no shadows, so a tile is drawn as its sets only when all of it lies beyond
// the shadow distance (its plants then cast none either).
#include "components/camera.h"
#include "components/fade_alpha.h"
#include "components/lod_state.h"
#include "components/tile.h"
#include "components/tile_visibility.h"
#include "ecs/system.h"
#include "scenarios/scenario.h"
#include "resources/lod_policy.h"
#include "setup/tile_point_sets.h"

namespace sylva {

inline constexpr double k_aggregate_distance_factor = 3.0;
inline constexpr double k_aggregate_ramp = 0.25;

// This frame's prefix of every tile set (0: not drawn), a world resource.
struct tile_point_draws {
    std::vector<std::uint32_t> counts;  // per tile_point_sets::parts
    std::vector<std::uint8_t> splats;   // per part: 1 when a line set draws `counts` splats
    std::uint32_t tiles = 0;            // tiles drawn as their sets (in part or whole)
    std::uint32_t plants = 0;           // plants they stand for
    // Per tile, reused every frame (no allocation in a warm frame): the share its plants allow,
    // the share its sets are drawn at, and the tile drawing it (k_no_eco_tile: none).
    std::vector<float> allowed;
    std::vector<float> share;
    std::vector<std::uint32_t> covering;
};

// The prefix lengths of one tile's sets seen from `distance_m` at full density, capped at what
// each set holds, and the share of full density the sets can draw (1 when every set holds enough;
// a set holding n of the p samples Eq. 1 or Eq. 2 asks for gives n / p; 0 when a line set would
// be polygons). `sample_distance` is d' on the image plane; with `fog_density_per_m`, splats are
// spaced by fog_sample_distance at the tile's distance (point_line_lod.h). Pure, for tests.
double tile_prefixes(const tile_point_sets& sets, std::uint32_t tile, double distance_m,
                     double sample_distance, double splat_factor, std::vector<std::uint32_t>& counts,
                     std::vector<std::uint8_t>& splats, double fog_density_per_m = 0.0);

// The distance ramp of a tile of `radius_m` whose centre is `distance_m` from the eye: 0 nearer
// than k_aggregate_distance_factor radii or where the tile reaches into the shadow distance, 1
// from (1 + k_aggregate_ramp) times that, linear between.
double tile_distance_share(double distance_m, double radius_m, double shadow_distance_m);

struct aggregate_eco_tiles_system {
    static constexpr std::string_view k_name = "aggregate_eco_tiles";
    static constexpr ecs::phase k_phase = ecs::phase::transition;
    using reads = ecs::reads<camera, tile, tile_visibility, lod_policy, tile_point_sets, shadow_settings>;
    using writes = ecs::writes<lod_state, fade_alpha, tile_point_draws>;
    static void run(ecs::system_context<aggregate_eco_tiles_system>& ctx);
};

}  // namespace sylva
