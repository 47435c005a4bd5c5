#pragma once
// Generated textures: leaf cards, bark and ground. Colours are linear albedo (the renderer
// samples them as linear RGBA8 and builds the mipmaps). Deterministic: no seed argument, the
// same call always gives the same texels.
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "models/image/image.h"

namespace sylva {

// A leaf card texture for a tree generator ("broadleaf": a spray of ovate leaves with midribs
// and veins; "conifer": a twig with needles) on a transparent background: alpha 255 inside,
// 0 outside, anti-aliased at the edge. The stalk is at the bottom row (v = 1 on the card),
// the tip at the top (v = 0). Throws std::invalid_argument for an unknown generator.
image_rgba8 generate_leaf_texture(std::string_view generator, std::uint32_t size);

// Furrowed bark, opaque, tiling in both directions (u around the stem, v along it).
image_rgba8 generate_bark_texture(std::string_view generator, std::uint32_t size);

// Grass and soil, opaque, tiling seamlessly (periodic noise).
image_rgba8 generate_ground_texture(std::uint32_t size);

// Writes the image with OpenImageIO (format from the extension, e.g. .png); throws
// std::runtime_error naming the file if it cannot be written.
void write_image(const image_rgba8& image, const std::filesystem::path& path);

}  // namespace sylva
