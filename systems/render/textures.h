#pragma once
// Texture uploads: generated RGBA8 images become mipmapped 2D array textures (one layer per
// species, so one multi-draw covers every species) with trilinear, anisotropic filtering.
#include <span>

#include "models/image.h"
#include "systems/render/gl_objects.h"

namespace sylva::render {

// Every image must have the same size; throws std::invalid_argument otherwise.
gl_texture make_texture_array(std::span<const image_rgba8> layers, bool repeat);
// A linear RGB float texture (sky radiance), clamped vertically, repeating around the horizon.
gl_texture make_float_texture(int width, int height, const float* rgb);

}  // namespace sylva::render
