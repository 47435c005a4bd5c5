#pragma once
// Small helpers shared by the texture generators (models/generate/textures.cpp, models/generate/plant_textures.cpp):
// an empty square RGBA8 image, 0..1 to byte conversion, texel stores, and the leaf albedo both
// use. Internal to models/.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <stdexcept>

#include "models/image/image.h"

namespace sylva::texture_paint {

constexpr float k_pi = 3.14159265358979f;
// Linear albedo of green leaves (they reflect 5-15 % in the visible).
constexpr glm::vec3 k_leaf_green{0.040f, 0.095f, 0.018f};

inline std::uint8_t to_byte(float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

// A transparent black size x size image; throws for size 0.
inline image_rgba8 make_image(std::uint32_t size) {
    if (size == 0) throw std::invalid_argument("texture size must be > 0");
    image_rgba8 image;
    image.width = image.height = size;
    image.texels.assign(std::size_t(size) * size * 4, 0);
    return image;
}

inline void store(image_rgba8& image, std::uint32_t x, std::uint32_t y, glm::vec3 c, float alpha) {
    std::uint8_t* t = image.at(x, y);
    t[0] = to_byte(c.r);
    t[1] = to_byte(c.g);
    t[2] = to_byte(c.b);
    t[3] = to_byte(alpha);
}

}  // namespace sylva::texture_paint
