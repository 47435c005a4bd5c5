#pragma once
// Whole-image operations on image_rgba8.
#include <cstdint>

#include "models/image/image.h"

namespace sylva {

// Averages each factor x factor block (a box filter): the resolve of a supersampled render.
// Width and height must be multiples of factor; throws std::invalid_argument otherwise.
image_rgba8 box_downsample(const image_rgba8& image, std::uint32_t factor);

// Repeats each texel as a factor x factor block (nearest-neighbour upsampling): an atlas keeps
// its layout in normalised coordinates, so a smaller atlas can join a texture array of larger
// layers unchanged. Throws std::invalid_argument for factor 0.
image_rgba8 replicate_upsample(const image_rgba8& image, std::uint32_t factor);

}  // namespace sylva
