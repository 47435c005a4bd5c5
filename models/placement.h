#pragma once
// Seeded placement of one plant population on the terrain.
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "models/terrain.h"

namespace sylva {

struct placement {
    glm::dvec2 xz{0.0};      // world metres, terrain-centred
    float scale = 1.0f;      // uniform in [scale_min, scale_max]
    float yaw = 0.0f;        // radians, [0, 2 pi)
    std::uint32_t seed = 0;  // per-plant variation seed
    std::uint16_t tint = 0;  // per-plant colour variation, 0..65535
};

// Dart throwing with a minimum spacing (Poisson-disk-like, Cook 1986 "Stochastic sampling in
// computer graphics"; the background grid of cell size r/sqrt(2) holding at most one point is
// from Bridson 2007 "Fast Poisson disk sampling in arbitrary dimensions"). Candidates on slopes
// steeper than max_slope_deg are rejected. Stops after `count` plants or a bounded number of
// attempts, so it may return fewer; the order and content depend only on the arguments.
// area = {x0, z0, x1, z1}, x0 < x1, z0 < z1; points lie in [x0, x1) x [z0, z1).
std::vector<placement> place_population(const heightfield& terrain, std::array<double, 4> area,
                                        std::uint32_t count, float min_spacing_m, float scale_min,
                                        float scale_max, float max_slope_deg, std::uint64_t seed);

}  // namespace sylva
