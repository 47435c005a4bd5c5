#pragma once
// Deussen 2002 §6.2: "In distant views only this very sparse point representation is used.
// When zooming in, all the plants of the eco file are displayed." Walks the eco tiles from the
// roots (after selection, under the point/line representation): a visible tile far enough away
// (at least k_aggregate_distance_factor times its radius) whose sets hold enough samples for
// Eq. 1 and Eq. 2 at that distance is drawn as its sets' prefixes, and its plants are not
// drawn at all (lod_state none); otherwise its children are tried, and the plants of leaf tiles
// that do not qualify are drawn one by one as usual. Aggregated tiles cast no shadows, so a
// tile is aggregated only when all of it lies beyond the shadow distance.
#include "components/camera.h"
#include "components/lod_state.h"
#include "components/tile.h"
#include "components/tile_visibility.h"
#include "ecs/system.h"
#include "scenarios/scenario.h"
#include "resources/lod_policy.h"
#include "setup/tile_point_sets.h"

namespace sylva {

inline constexpr double k_aggregate_distance_factor = 3.0;

// This frame's prefix of every tile set (0: not drawn), a world resource.
struct tile_point_draws {
    std::vector<std::uint32_t> counts;  // per tile_point_sets::parts
    std::vector<std::uint8_t> splats;   // per part: 1 when a line set draws `counts` splats
    std::uint32_t tiles = 0;            // tiles drawn as their sets
    std::uint32_t plants = 0;           // plants they stand for
};

// The prefix lengths of one tile's sets seen from `distance_m`, or nothing when some set holds
// too few samples (or a line set would be polygons): then the tile is not drawn as a whole.
// `sample_distance` is d' on the image plane; with `fog_density_per_m`, splats are spaced by
// fog_sample_distance at the tile's distance (point_line_lod.h). Pure, for tests.
bool tile_prefixes(const tile_point_sets& sets, std::uint32_t tile, double distance_m,
                   double sample_distance, double splat_factor, std::vector<std::uint32_t>& counts,
                   std::vector<std::uint8_t>& splats, double fog_density_per_m = 0.0);

struct aggregate_eco_tiles_system {
    static constexpr std::string_view k_name = "aggregate_eco_tiles";
    static constexpr ecs::phase k_phase = ecs::phase::transition;
    using reads = ecs::reads<camera, tile, tile_visibility, lod_policy, tile_point_sets, shadow_settings>;
    using writes = ecs::writes<lod_state, tile_point_draws>;
    static void run(ecs::system_context<aggregate_eco_tiles_system>& ctx);
};

}  // namespace sylva
