#pragma once
// Luft 2007's claim about a crown's look, measured (issue 22, "less noise, same shape"): plain
// local lighting of thousands of randomly oriented leaves fills a crown with high-frequency
// noise; the realigned normals light it by its shape. Inside crown masks: the energy of the
// image's high frequencies (the variance of a Laplacian of luma) and the mean luma.
#include <cstdint>
#include <vector>

#include "models/image/image.h"

namespace sylva {

// Pixels of `mask` (non-zero: plant) whose (2·radius + 1)² neighbourhood is all plant, so a
// silhouette's edge against sky or ground never counts as the crown's own texture.
std::vector<std::uint8_t> mask_interior(const std::vector<std::uint8_t>& mask, std::uint32_t width,
                                        std::uint32_t height, std::uint32_t radius = 2);

struct crown_texture {
    std::size_t pixels = 0;
    double mean_luma = 0.0;           // Rec. 709 luma of the sRGB values, 0 .. 255
    double mean_laplacian = 0.0;      // of 4·L(x, y) − L(x±1, y) − L(x, y±1) over the pixels
    double laplacian_variance = 0.0;
};

// Two measurements' pixels pooled into one (as if one mask had covered both images).
crown_texture pooled(const crown_texture& a, const crown_texture& b);

// Over the pixels `interior` marks (their 4-neighbours must lie in the image: mask_interior with
// radius >= 1 guarantees it). Images and masks of the same size; none marked gives zeros.
crown_texture crown_texture_of(const image_rgba8& image, const std::vector<std::uint8_t>& interior);

}  // namespace sylva
