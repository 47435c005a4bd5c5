#include "models/generate/plant_textures.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <stdexcept>

#include "models/noise.h"
#include "models/generate/texture_paint.h"

namespace sylva {
namespace {

using namespace texture_paint;

constexpr std::uint64_t k_texture_seed = 0x91a7u;

// Linear albedos in the ranges of models/generate/textures.cpp.
constexpr glm::vec3 k_blade_green{0.055f, 0.12f, 0.025f};
constexpr glm::vec3 k_frond_green{0.035f, 0.10f, 0.02f};
constexpr glm::vec3 k_petal{0.55f, 0.05f, 0.22f};  // magenta: a campion / cranesbill look
constexpr glm::vec3 k_centre{0.60f, 0.42f, 0.03f};

struct texel_sample {
    float distance;  // > 0 inside, texture units of the region
    glm::vec3 colour;
};

// Rasterises `shape` (coordinates 0..1 over the region, y down) into the pixel rectangle
// [x0, x1) x [y0, y1), with one texel of anti-aliasing at the outline.
template <class Shape>
void fill_region(image_rgba8& image, std::uint32_t x0, std::uint32_t y0, std::uint32_t x1, std::uint32_t y1, Shape shape) {
    const float w = float(x1 - x0);
    const float h = float(y1 - y0);
    for (std::uint32_t y = y0; y < y1; ++y) {
        for (std::uint32_t x = x0; x < x1; ++x) {
            const glm::vec2 p{(float(x - x0) + 0.5f) / w, (float(y - y0) + 0.5f) / h};
            const texel_sample s = shape(p);
            const float alpha = std::clamp(s.distance * std::min(w, h) + 0.5f, 0.0f, 1.0f);
            store(image, x, y, alpha > 0.0f ? s.colour : glm::vec3(0.0f), alpha);
        }
    }
}

float grain(glm::vec2 p, float scale) { return value_noise(double(p.x) * scale, double(p.y) * scale, k_texture_seed); }

// A leaf outline symmetric about x = 0.5, tip at the top (y = 0.04), base at y = 0.96:
// half width as a function of s (0 base, 1 tip).
template <class HalfWidth>
texel_sample symmetric_leaf(glm::vec2 p, glm::vec3 colour, HalfWidth half_width) {
    const float s = (0.96f - p.y) / 0.92f;
    const float side = std::abs(p.x - 0.5f);
    const float hw = s >= 0.0f && s <= 1.0f ? half_width(s) : 0.0f;
    const float distance = std::min({hw - side, s * 0.92f, (1.0f - s) * 0.92f});
    const float across = hw > 0.0f ? side / hw : 1.0f;
    const float midrib = across < 0.08f ? 0.35f : 0.0f;
    const glm::vec3 c = colour * (0.85f + 0.3f * grain(p, 30.0f)) * (1.0f - 0.2f * across * across);
    return {distance, c + (glm::vec3(0.09f, 0.17f, 0.05f) - c) * midrib};
}

}  // namespace

image_rgba8 generate_grass_texture(std::uint32_t size) {
    image_rgba8 image = make_image(size);
    // The blade strip is already narrow in geometry: the texture fills its width (with a clear
    // texel each side for clamped mips) and only draws the pointed tip and the veins.
    fill_region(image, 0, 0, size, size, [](glm::vec2 p) {
        const float s = (1.0f - p.y);
        const float hw = 0.46f * std::min(1.0f, (1.0f - s) / 0.15f);
        const float vein = 0.9f + 0.1f * std::cos(p.x * 7.0f * 2.0f * k_pi);
        const glm::vec3 c = k_blade_green * vein * (0.75f + 0.35f * s) * (0.9f + 0.2f * grain(p, 20.0f));
        return texel_sample{std::min(hw - std::abs(p.x - 0.5f), p.y - 0.01f), c};
    });
    return image;
}

image_rgba8 generate_flower_atlas(std::uint32_t size) {
    image_rgba8 image = make_image(size);
    const std::uint32_t half = size / 2;
    // Leaf: lanceolate, widest a third of the way up.
    fill_region(image, 0, 0, half, size, [](glm::vec2 p) {
        return symmetric_leaf(p, k_leaf_green, [](float s) { return 0.42f * std::sin(k_pi * std::pow(s, 0.75f)); });
    });
    // Petal: obovate (widest near the tip), rounded tip with a notch, paler towards the base.
    fill_region(image, half, 0, size, half, [](glm::vec2 p) {
        texel_sample t = symmetric_leaf(p, k_petal, [](float s) {
            const float notch = 1.0f - 0.25f * std::exp(-std::pow((s - 1.0f) / 0.06f, 2.0f));
            return 0.45f * std::sqrt(std::max(0.0f, std::sin(k_pi * 0.5f * std::min(s * 1.25f, 1.0f) + 0.0f))) *
                   std::sqrt(std::max(0.0f, 1.0f - std::pow(s, 6.0f))) * notch;
        });
        const float s = (0.96f - p.y) / 0.92f;
        t.colour = glm::mix(glm::vec3(0.75f, 0.55f, 0.6f), k_petal, std::clamp(s * 3.0f, 0.0f, 1.0f)) *
                   (0.9f + 0.2f * grain(p, 25.0f));
        return t;
    });
    // Centre disc: stamens as speckles on a yellow disc.
    fill_region(image, half, half, size, size, [](glm::vec2 p) {
        const float r = glm::length(p - glm::vec2(0.5f));
        return texel_sample{0.44f - r, k_centre * (0.7f + 0.6f * grain(p, 40.0f)) * (1.0f - 0.6f * r)};
    });
    return image;
}

image_rgba8 generate_fern_texture(std::uint32_t size) {
    image_rgba8 image = make_image(size);
    fill_region(image, 0, 0, size, size, [](glm::vec2 p) {
        return symmetric_leaf(p, k_frond_green, [](float s) {
            const float lobes = 0.75f + 0.25f * std::abs(std::sin(s * 11.0f * k_pi));
            return 0.4f * std::pow(1.0f - s, 0.8f) * std::min(1.0f, s * 6.0f + 0.3f) * lobes;
        });
    });
    return image;
}

image_rgba8 generate_stem_texture(std::uint32_t size) {
    image_rgba8 image = make_image(size);
    for (std::uint32_t y = 0; y < size; ++y) {
        for (std::uint32_t x = 0; x < size; ++x) {
            // Lengthwise ribs (integer count around: tiles in u), fine streaks along.
            const float u = (float(x) + 0.5f) / float(size);
            const float rib = 0.85f + 0.15f * std::cos(8.0f * 2.0f * k_pi * u);
            const glm::vec3 c = glm::vec3(0.06f, 0.11f, 0.03f) * rib;
            std::uint8_t* t = image.at(x, y);
            t[0] = to_byte(c.r);
            t[1] = to_byte(c.g);
            t[2] = to_byte(c.b);
            t[3] = 255;
        }
    }
    return image;
}

}  // namespace sylva
