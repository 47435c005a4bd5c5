#pragma once
// Aerial perspective: the exponential fog that shaders/common.glsl apply_fog mixes towards the
// horizon's colour. Shared with the level-of-detail rules, which spend samples on a plant by how
// much of it the fog leaves visible (lod/point_line_lod.h fog_sample_distance).
#include <cmath>

namespace sylva {

// Fog density per metre: a surface r metres away keeps T(r) = exp(−density·r) of its own
// colour, the rest is the fog's (apply_fog: mix(colour, fog, 1 − T)).
inline constexpr double k_fog_density_per_m = 0.0009;

// T(r), the fraction of a surface's colour (and so of its contrast) left at `distance_m`.
inline double fog_transmittance(double distance_m, double density_per_m = k_fog_density_per_m) {
    return std::exp(-density_per_m * distance_m);
}

}  // namespace sylva
