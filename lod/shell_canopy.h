#pragma once
// The sunlight a shell slice receives through the slices above it. The plants a shell stands
// for are not drawn as geometry, so they cast nothing into the shadow map (Behrendt 2005 §4 shades
// plants with shadow maps [Wil78]), and unshadowed slices lit the far field's crowns as if every
// leaf stood in full sun: on docs/measure_shells.py's far fields the shells were about 0.06 (of 1)
// brighter than the plants they stand for, the cause of most of their FLIP. Their own slices are
// an opacity shadow map of those plants (Kim and Neumann 2001, "Opacity shadow maps": layers of
// accumulated opacity along the light), taken along the vertical: the transmittance of the
// slices above slice k of one pyramid level at a texel,
//   T_k = Π_{j > k} (1 − α_j)                                  (Beer–Lambert over the slabs)
// with α_j slice j's (premultiplied) alpha. The sun at elevation e crosses each slab over 1/sin e
// its thickness, so a canopy of the same leaves everywhere lets T_k^(1/sin e) through
// (shaders/shell.frag): the sideways offset of the sun's path through the slabs is left out, which
// in a far field of many crowns changes where the shade falls but not how much there is.
//
// Only the sun is attenuated: the plants' own rungs receive the sky unoccluded (normal-lit) or
// with their own transfer's occlusion (SH), and attenuating it too took SSIM from 0.928 to 0.921
// at 20° (docs/measure_shells.py's far field, session 47).
#include <span>
#include <vector>

#include "models/image/image.h"

namespace sylva {

// `normal` and `colour`: one pyramid level's slices, bottom first, all of one size. Returns
// `normal` with each texel's alpha replaced by T_k in 8 bits (255 under an empty sky). Throws
// std::invalid_argument when the counts or sizes differ.
std::vector<image_rgba8> with_canopy_transmittance(std::vector<image_rgba8> normal, std::span<const image_rgba8> colour);

}  // namespace sylva
