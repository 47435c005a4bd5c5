#pragma once
// An 8-bit RGBA image in memory, rows top to bottom. Generated textures and captured frames.
#include <cstdint>
#include <vector>

namespace sylva {

struct image_rgba8 {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> texels;  // width * height * 4

    std::uint8_t* at(std::uint32_t x, std::uint32_t y) { return &texels[(std::size_t(y) * width + x) * 4]; }
    const std::uint8_t* at(std::uint32_t x, std::uint32_t y) const {
        return &texels[(std::size_t(y) * width + x) * 4];
    }
};

}  // namespace sylva
