#pragma once
// Whole-image operations on image_rgba8.
#include <cstdint>

#include "models/image.h"

namespace sylva {

// Averages each factor x factor block (a box filter): the resolve of a supersampled render.
// Width and height must be multiples of factor; throws std::invalid_argument otherwise.
image_rgba8 box_downsample(const image_rgba8& image, std::uint32_t factor);

}  // namespace sylva
