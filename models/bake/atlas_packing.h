#pragma once
// Rectangles packed into one texture atlas (the billboard clouds' atlas, Behrendt 2005 §2.3:
// "All billboard textures are stored in one texture atlas"), with stb_rect_pack's skyline
// packer from Debian's libstb-dev. Its qsort is replaced by a stable sort, so equal-sized
// rectangles land in the same places on every C library and the atlas is byte-identical.
#include <cstdint>
#include <glm/vec2.hpp>
#include <optional>
#include <span>
#include <vector>

namespace sylva {

struct atlas_rect {
    std::uint32_t x = 0;  // top-left texel, rows top to bottom
    std::uint32_t y = 0;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
};

// Places a width x height rectangle per size (same order) inside a width x height atlas, with at
// least `gutter` free texels between any two and between each and the atlas border (room for
// filtering and a few mip levels without bleeding). Nothing when they do not all fit. Throws
// std::invalid_argument for a zero size or an atlas of more than 2^24 texels per side.
std::optional<std::vector<atlas_rect>> pack_atlas(std::span<const glm::uvec2> sizes, std::uint32_t width,
                                                  std::uint32_t height, std::uint32_t gutter);

// True when two rectangles share a texel.
bool overlaps(const atlas_rect& a, const atlas_rect& b);

}  // namespace sylva
