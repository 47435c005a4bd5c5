#pragma once
// Texture uploads: generated RGBA8 images become mipmapped 2D array textures (one layer per
// species, so one multi-draw covers every species) with trilinear filtering.
#include <cstdint>
#include <span>

#include "models/image/image.h"
#include "systems/render/gl_objects.h"

namespace sylva::render {

// Every image must have the same size; throws std::invalid_argument otherwise. With
// `alpha_tested`, mip levels keep the alpha-test coverage of level 0 (see below).
// With `alpha_tested`, mips keep each image's alpha-test coverage (preserve_alpha_coverage); an
// atlas of images side by side gives `columns`, the texel column each image begins at and the
// width last (ascending from 0), and each keeps its own (one scale for an atlas would let one
// image's coverage change another's; empty: the layer is one image).
gl_texture make_texture_array(std::span<const image_rgba8> layers, bool repeat,
                              bool alpha_tested = false,
                              std::span<const std::uint32_t> columns = {});

// The next mip level: a 2x2 box filter (sizes halve, never below 1).
image_rgba8 downsample(const image_rgba8& image);
// The next mip level of a cut-out (alpha-tested) image: colour averaged over the texels it
// covers weighted by their alpha, alpha averaged plainly. A plain box filter mixes the colour
// of transparent texels (black, in the generated textures) into every level, so distant
// foliage sampled from small mips turns darker than the same leaves up close.
image_rgba8 downsample_cut_out(const image_rgba8& image);
// Fills the colour of every fully transparent texel with that of the nearest opaque ones
// (push-pull over downsample_cut_out levels); alpha and opaque texels are left as they were.
void bleed_colour(image_rgba8& image);
// Fraction of texels whose alpha passes the test alpha >= 0.5 after scaling alpha by `scale`.
float alpha_coverage(const image_rgba8& image, float scale = 1.0f);
// Castaño 2010, "Computing alpha mipmaps": averaging alpha in smaller mips pushes cut-out
// foliage below the alpha-test threshold, so leaves thin out and vanish with distance. Scales
// the level's alpha (binary search) so its coverage matches `target` coverage.
void preserve_alpha_coverage(image_rgba8& level, float target);
// The same for the columns [first, last) of `level` alone.
void preserve_alpha_coverage(image_rgba8& level, float target, std::uint32_t first,
                             std::uint32_t last);
// A linear RGB float texture (sky radiance), clamped vertically, repeating around the horizon.
gl_texture make_float_texture(int width, int height, const float* rgb);

}  // namespace sylva::render
