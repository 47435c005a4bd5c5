#pragma once
// Behrendt 2005 §3.3: the shell slices are stored with premultiplied alpha, (r·α, g·α, b·α, α),
// and blended with the modified equation c'_dest = c_source + c_dest·(1 − α_source) (the paper's
// ∘; GL_ONE, GL_ONE_MINUS_SRC_ALPHA), which is associative, so a slice pyramid can merge slices
// ahead of time and a merged slice blends like its slices one after another. The standard
// equation c'_dest = c_source·α_source + c_dest·(1 − α_source) (the paper's •) is not, which is
// why a pyramid built with it shifts the colours when the slice count changes.
//
// Colours here are linear RGBA in [0, 1]; a "frame" colour F is what the framebuffer holds.
#include <cstdint>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

#include "models/image/image.h"

namespace sylva {

// (r·α, g·α, b·α, α).
glm::vec4 premultiply(const glm::vec4& straight);

// c • F: the standard equation, colour and alpha alike: c·α + F·(1 − α), `c` straight.
glm::vec4 blend_standard(const glm::vec4& c, const glm::vec4& frame);

// c ∘ F: the modified equation, colour and alpha alike: c + F·(1 − α), `c` premultiplied.
// c^pre ∘ F equals c • F in rgb; only alpha differs (the paper's "≈": α + α_F(1 − α) against
// α² + α_F(1 − α)), and alpha is not displayed.
glm::vec4 blend_premultiplied(const glm::vec4& c, const glm::vec4& frame);

// The slices of a shell seen from above are blended bottom first; a pyramid level merges each
// pair (lower 2k, upper 2k + 1) into upper ∘ lower, so (upper ∘ lower) ∘ F = upper ∘ (lower ∘ F).
// An odd top slice is carried up as it is. Every slice is premultiplied RGBA8 of one size;
// rounding to 8 bits costs at most half a step per merge.
image_rgba8 merge_slices(const image_rgba8& lower, const image_rgba8& upper);
std::vector<image_rgba8> next_pyramid_level(const std::vector<image_rgba8>& slices);
// For measurement only: the pyramid a renderer with the standard equation would build, each pair
// blended onto a cleared target, upper • (lower • 0), from straight-colour slices (unpremultiply
// the bake's), and then drawn with • too. (upper • (lower • 0)) • F is not upper • (lower • F):
// where the slices are partly transparent the merged slice shows less of what lies behind and
// darkens the colour, so colours shift where a level replaces its slices (§3.3's reason for ∘).
image_rgba8 unpremultiply_slice(const image_rgba8& premultiplied);
image_rgba8 merge_slices_standard(const image_rgba8& lower, const image_rgba8& upper);
std::vector<image_rgba8> next_pyramid_level_standard(const std::vector<image_rgba8>& slices);
// The same for the slices' normal images (rgb n·0.5 + 0.5 straight, a coverage): the normal
// seen from above, the upper's over the lower's by their coverage, and coverage as alpha merges.
image_rgba8 merge_normal_slices(const image_rgba8& lower, const image_rgba8& upper);
std::vector<image_rgba8> next_normal_pyramid_level(const std::vector<image_rgba8>& slices);
// The same for the slices' SH transfer (models/bake/shell_bake.h shell_stack::transfer,
// k_transfer_pages pages a slice, page 4's alpha the coverage): every coefficient the upper's over
// the lower's by coverage, t = (t_u·α_u + t_l·α_l·(1 − α_u)) / (α_u + α_l·(1 − α_u)) (Behrendt 2005
// §4's transfer under §3.3's merge: what is seen from above is lit by the transfer of what
// covers it), the coverage merged as alpha. `lower` and `upper` are one slice's pages each.
std::vector<image_rgba8> merge_transfer_slices(std::span<const image_rgba8> lower, std::span<const image_rgba8> upper);
// `slices` holds k_transfer_pages pages per slice, slice-major.
std::vector<image_rgba8> next_transfer_pyramid_level(const std::vector<image_rgba8>& slices);

}  // namespace sylva
