#pragma once
// Behrendt 2005 §3.3, level of detail on shell textures: far away the slices are too close on
// screen to matter one by one, so pairs of slices are replaced by their pre-blended merge (the
// slice pyramid, lod/shell_blending.h). To avoid a pop, "the two slices are moved closer together
// until they finally touch. Then they can be replaced by a single plane", by a vertical offset
// that is piecewise linear in the distance.
//
// Here a level L draws S / 2^L slices, slice j covering the slab [j, j + 1)·2^L·h above the ground
// (h: the bake's slice height) and drawn at its centre (j + ½)·2^L·h. The level follows the
// slices' spacing on screen: λ = log2(d · p_min / (h · pixels per radian)), the level at which
// 2^L·h seen from distance d is p_min pixels; L = ⌊λ⌋ (within [0, max_level]) and, over the last
// `band` of each unit of λ, the merge t rises linearly from 0 to 1: each pair (2k, 2k + 1) of
// level L moves by t toward its common centre, the centre of slice k of level L + 1, which
// replaces the pair where t reaches 1 (λ crosses the next integer) at the same height.
#include <cstdint>
#include <glm/vec3.hpp>

namespace sylva {

struct shell_level {
    std::uint32_t level = 0;  // L: slices of 2^L bake slices
    float merge = 0.0f;       // t in [0, 1]: how far each pair of level L has moved together
};

// The level and merge at distance `distance_m` (clamped below at 1 mm). `pixels_per_radian`:
// the viewport height over the vertical field of view; `min_spacing_px` (p_min): slices closer
// than this on screen are merged; `band` in (0, 1]: the share of each level's distance range
// (in λ) over which its pairs move together. At max_level the merge stays 0.
shell_level shell_level_at(float distance_m, float slice_height_m, float pixels_per_radian, float min_spacing_px,
                           std::uint32_t max_level, float band);

// The distance to give shell_level_at for a point of a slice seen along `eye_to_point`: a
// vertical offset Δy there shows as Δy·sin θ / d on screen (θ between the ray and the vertical),
// so slices seen from above lie closer on screen and merge sooner: d / sin θ, with sin θ at
// least 1/1000 (straight down, one slice shows exactly what the stack would: the merged pyramid
// levels are exact where slices project onto each other). The shell vertex shader decides each
// triangle's level with it (shaders/shell.vert).
float shell_level_distance(const glm::vec3& eye_to_point);

// The levels of a pyramid over `slices` bake slices: level L holds ⌈slices / 2^L⌉, the last one
// (at most 1 + ⌈log2 slices⌉ levels; 0 slices: none).
std::uint32_t shell_pyramid_levels(std::uint32_t slices);
// The slices at `level` of that pyramid: ⌈slices / 2^level⌉, pairs merged level by level.
std::uint32_t shell_slices_at_level(std::uint32_t slices, std::uint32_t level);

// The height above the ground at which slice `j` of level `level` is drawn when its pairs have
// merged by `merge`: its centre (j + ½)·2^L·h moved by `merge` toward the centre of its pair
// (2⌊j/2⌋ + 1)·2^L·h. An unpaired top slice (an odd count) does not move.
float shell_slice_height(std::uint32_t j, std::uint32_t level, float merge, float slice_height_m,
                         std::uint32_t slices_at_level);

}  // namespace sylva
