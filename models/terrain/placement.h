#pragma once
// Seeded placement of one plant population on the terrain.
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "models/random.h"
#include "models/terrain/density.h"
#include "models/terrain/terrain.h"

namespace sylva {

struct placement {
    glm::dvec2 xz{0.0};      // world metres, terrain-centred
    float scale = 1.0f;      // uniform in [scale_min, scale_max]
    float yaw = 0.0f;        // radians, [0, 2 pi)
    std::uint32_t seed = 0;  // per-plant variation seed
    std::uint16_t tint = 0;  // per-plant colour variation, 0..65535
};

// A plant at `xz` with its scale, yaw, variation seed and tint drawn from `random` in that
// order (both placement modes and models/terrain/wang_tiles.h).
placement make_placement(glm::dvec2 xz, float scale_min, float scale_max, rng& random);

// What a population may grow on and how it is spread. area = {x0, z0, x1, z1}, x0 < x1,
// z0 < z1; points lie in [x0, x1) x [z0, z1).
struct placement_rules {
    std::array<double, 4> area{};
    std::uint32_t count = 0;     // at most this many plants
    float min_spacing_m = 0.0f;  // no two plants closer (both modes)
    float scale_min = 1.0f;
    float scale_max = 1.0f;
    float max_slope_deg = 90.0f;   // steeper ground is rejected
    float min_altitude_m = -1e9f;  // terrain height outside [min, max] is rejected
    float max_altitude_m = 1e9f;
    bool poisson = true;  // true: dart throwing (below); false: jittered grid
    // Acceptance probability over the area (u along x, v along z); nullptr: 1 everywhere. Not
    // owned; must outlive the call.
    const density_map* density = nullptr;
};

// poisson: dart throwing as below, plus the altitude rule and, with a density map, a candidate
// kept with probability density(u, v) (so with a sparse map fewer than `count` may be placed
// within the bounded attempts). jittered: a grid of about `count` square cells no smaller than
// min_spacing_m, one candidate per cell jittered inside the cell but at least min_spacing_m / 2
// from its sides (so neighbours keep the spacing), then the same rules; cells are visited row
// by row and the result is cut at `count`. Both are deterministic in (terrain, rules, seed).
std::vector<placement> place_population(const heightfield& terrain, const placement_rules& rules,
                                        std::uint64_t seed);

// Dart throwing with a minimum spacing (Poisson-disk-like, Cook 1986 "Stochastic sampling in
// computer graphics"; the background grid of cell size r/sqrt(2) holding at most one point is
// from Bridson 2007 "Fast Poisson disk sampling in arbitrary dimensions"). Candidates on slopes
// steeper than max_slope_deg are rejected. Stops after `count` plants or a bounded number of
// attempts, so it may return fewer; the order and content depend only on the arguments.
// The same as the placement_rules overload with poisson = true and no altitude or density rule.
std::vector<placement> place_population(const heightfield& terrain, std::array<double, 4> area,
                                        std::uint32_t count, float min_spacing_m, float scale_min,
                                        float scale_max, float max_slope_deg, std::uint64_t seed);

}  // namespace sylva
