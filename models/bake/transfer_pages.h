#pragma once
// Precomputed radiance transfer as textures (Behrendt 2005 §4: "we store the
// Gouraud-interpolated vectors in an extra texture"), for the representations whose surface is
// an image: billboard clouds and crossed billboards. 18 coefficients per texel in
// k_transfer_pages RGBA8 pages of the atlas's layout: channels 0..8 (pages 0, 1 and page 2's r)
// the transfer of the side the billboard's viewer sees, 9..17 of the other side, each encoded
// (T / k_transfer_page_range) * 0.5 + 0.5 in 8 bits. Zero transfer is byte 128.
#include <cstdint>
#include <string>
#include <vector>

#include "models/cache/bake_cache.h"
#include "models/bake/billboard_bake.h"
#include "models/image/image.h"

namespace sylva {

constexpr std::uint32_t k_transfer_pages = 5;
// Transfer coefficients stay within about ±1.02 (the clamped cosine's band-1 coefficient,
// sqrt(pi/3), is the largest), so ±1.25 keeps every one with room, at 0.01 per step. Mirrored
// in shaders/transfer.glsl.
constexpr float k_transfer_page_range = 1.25f;

std::uint8_t encode_transfer(float t);
float decode_transfer(std::uint8_t byte);

// k_transfer_pages pages of width x height holding zero transfer.
std::vector<image_rgba8> blank_transfer_pages(std::uint32_t width, std::uint32_t height);

// One billboard image's transfer (billboard_image::transfer, from a bake with a transfer
// source) into `pages` with its top-left texel at (x0, y0).
void blit_transfer(std::vector<image_rgba8>& pages, const billboard_image& image, std::uint32_t x0,
                   std::uint32_t y0);

// Bake-cache form: a count (0 or k_transfer_pages), then the pages. read_transfer_pages throws
// std::runtime_error naming `owner` on another count or a page not width x height.
void write_transfer_pages(binary_writer& out, const std::vector<image_rgba8>& pages);
std::vector<image_rgba8> read_transfer_pages(binary_reader& in, std::uint32_t width, std::uint32_t height,
                                             const std::string& owner);

}  // namespace sylva
