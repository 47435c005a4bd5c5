#pragma once
// The sun's shadow of the terrain as a height field of its own: for every height sample, the
// height H below which a point there is in the terrain's shadow,
//   H(p) = max(h(p), max_{t > 0} h(p + t s) - t tan(theta)),
// s the horizontal direction towards the sun, theta its elevation. A point (x, y, z) lies in
// the terrain's shadow exactly when y < H(x, z), whatever its height above the ground, so the
// ground shadows itself and the plants standing in a hill's shadow from one lookup, at any
// distance. The terrain is then no caster of the shadow cascades: on landscape it was 6.1 M of
// their 7.2 M fragments per frame (crossed billboards, 480x270), drawn into all three, and there
// it darkened no pixel the hills' heights do not (24 frames, identical images).
//
// Computed in one sweep from the sun's side (our own; no Debian library computes a height
// field's shadow): H(p) = max(h(p), H(q) - |q - p| tan(theta)) with q one sample column (or
// row: the axis along which s is longer) towards the sun, H(q) linear between the two samples
// of that column that q falls between. O(samples); the interpolation smooths the shadow's edge
// by about a sample.
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace sylva {

// `heights`: resolution^2 samples, row-major (z rows, x columns), `spacing` metres apart (the
// layout of models/terrain/terrain.h heightfield). `towards_sun`: unit. Writes resolution^2
// shadow heights into `shadow` (resized; no allocation when it already holds them). A sun
// overhead or at or below the horizon: H = h (overhead nothing is shadowed that the surface's
// own n.l does not darken; below the horizon the sun lights nothing anyway).
void terrain_shadow_heights(std::span<const float> heights, std::uint32_t resolution,
                            double spacing, glm::vec3 towards_sun, std::vector<float>& shadow);

}  // namespace sylva
