#pragma once
// Image encoding and decoding in memory through OpenImageIO, for textures inside glTF files.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "models/image/image.h"

namespace sylva {

// Decodes a PNG or JPEG held in memory to RGBA8 (grey and RGB get alpha 255). Throws
// std::runtime_error naming `what` when the bytes are not an image OpenImageIO can read.
image_rgba8 decode_image(std::span<const std::uint8_t> bytes, std::string_view what);

// Encodes the image as PNG bytes.
std::vector<std::uint8_t> encode_png(const image_rgba8& image);

// Filtered resize (OpenImageIO's default filter); returns a copy when the size already matches.
image_rgba8 resize_image(const image_rgba8& image, std::uint32_t width, std::uint32_t height);

}  // namespace sylva
