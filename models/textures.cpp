#include "models/textures.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/noise.h"
#include "models/random.h"
#include "models/tree_params.h"

namespace sylva {
namespace {

constexpr float k_pi = 3.14159265358979f;
constexpr std::uint64_t k_texture_seed = 0x7e47u;

// Linear albedos (roughly measured ranges: green leaves reflect 5-15% in the visible, bark and
// soil 10-25%), so the renderer's lighting, not the texture, sets the brightness.
constexpr glm::vec3 k_leaf_green{0.07f, 0.20f, 0.035f};
constexpr glm::vec3 k_needle_green{0.035f, 0.11f, 0.035f};
constexpr glm::vec3 k_twig_brown{0.14f, 0.09f, 0.05f};
constexpr glm::vec3 k_grass{0.07f, 0.15f, 0.035f};
constexpr glm::vec3 k_soil{0.16f, 0.11f, 0.06f};

std::uint8_t to_byte(float v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

image_rgba8 make_image(std::uint32_t size) {
    if (size == 0) throw std::invalid_argument("texture size must be > 0");
    image_rgba8 image;
    image.width = image.height = size;
    image.texels.assign(std::size_t(size) * size * 4, 0);
    return image;
}

void store(image_rgba8& image, std::uint32_t x, std::uint32_t y, glm::vec3 c, float alpha) {
    std::uint8_t* t = image.at(x, y);
    t[0] = to_byte(c.r);
    t[1] = to_byte(c.g);
    t[2] = to_byte(c.b);
    t[3] = to_byte(alpha);
}

// Centre of texel (x, y) in [0, 1]^2, y down like the rows.
glm::vec2 texel_centre(std::uint32_t x, std::uint32_t y, std::uint32_t size) {
    return {(float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size)};
}

void require_generator(std::string_view generator) {
    if (std::find(k_tree_preset_names.begin(), k_tree_preset_names.end(), generator) != k_tree_preset_names.end())
        return;
    throw std::invalid_argument("unknown tree generator \"" + std::string(generator) +
                                "\" for a texture (valid: broadleaf, conifer)");
}

// --- shapes with a signed distance (texture units, > 0 inside) and a colour at a point.

struct shape_sample {
    float distance = -1.0f;
    glm::vec3 colour{0.0f};
};

// A capsule from a to b: twigs and needles.
shape_sample capsule(glm::vec2 p, glm::vec2 a, glm::vec2 b, float radius, glm::vec3 colour) {
    const glm::vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return {radius - glm::length(p - (a + ab * t)), colour};
}

struct blade {
    glm::vec2 base;
    glm::vec2 axis;  // unit, base to tip
    float length;
    glm::vec3 colour;
};

// Ovate outline: half width ~ s^a (1 - s), widest at s = a / (1 + a) ~ 0.35 of the way to the
// tip, as in the ovate leaves of botany field guides; scaled to a maximum of 0.25 * length.
float ovate_half_width(float s) {
    constexpr float a = 0.55f;
    const float peak = std::pow(a / (1.0f + a), a) / (1.0f + a);
    return 0.25f * std::pow(std::max(s, 0.0f), a) * std::max(1.0f - s, 0.0f) / peak;
}

// Midrib, and lateral veins running from it towards the tip at about 45 degrees.
float vein_light(float s, float across) {
    const float midrib = across < 0.02f ? 1.0f : 0.0f;
    const float phase = s * 9.0f - across * 6.0f;
    const float vein = (phase - std::floor(phase)) < 0.1f && across < 0.85f ? 0.6f : 0.0f;
    return std::max(midrib, vein);
}

shape_sample leaf_blade(glm::vec2 p, const blade& b) {
    const glm::vec2 rel = p - b.base;
    const float along = glm::dot(rel, b.axis);
    const float side = std::abs(rel.x * b.axis.y - rel.y * b.axis.x);
    const float s = along / b.length;
    const float half_width = ovate_half_width(s) * b.length;
    const float distance = std::min({half_width - side, along, b.length - along});
    const float across = half_width > 0.0f ? side / half_width : 1.0f;
    const float shade = 0.85f + 0.3f * value_noise(double(p.x) * 40.0, double(p.y) * 40.0, k_texture_seed);
    const glm::vec3 lit = glm::vec3(0.16f, 0.30f, 0.08f);
    const glm::vec3 c = b.colour * shade * (1.0f - 0.25f * across * across);  // darker towards the rim
    return {distance, c + (lit - c) * 0.55f * vein_light(s, across)};
}

// Keeps the sample that covers the texel most; equal cover keeps the earlier (drawn on top).
void composite(shape_sample& best, const shape_sample& candidate) {
    if (candidate.distance > best.distance) best = candidate;
}

template <class Shapes>
image_rgba8 rasterise(std::uint32_t size, Shapes shapes) {
    image_rgba8 image = make_image(size);
    for (std::uint32_t y = 0; y < size; ++y) {
        for (std::uint32_t x = 0; x < size; ++x) {
            const shape_sample s = shapes(texel_centre(x, y, size));
            // One texel of anti-aliasing ramp across the outline.
            const float alpha = std::clamp(s.distance * float(size) + 0.5f, 0.0f, 1.0f);
            store(image, x, y, alpha > 0.0f ? s.colour : glm::vec3(0.0f), alpha);
        }
    }
    return image;
}

std::vector<blade> broadleaf_spray() {
    rng random(k_texture_seed, 1);
    auto tint = [&] { return k_leaf_green * glm::vec3(random.uniform(0.85f, 1.15f), random.uniform(0.85f, 1.15f), 1.0f); };
    auto dir = [](float deg) { return glm::vec2(std::sin(deg * k_pi / 180.0f), -std::cos(deg * k_pi / 180.0f)); };
    return {{{0.5f, 0.36f}, dir(0.0f), 0.32f, tint()},    {{0.5f, 0.54f}, dir(-47.0f), 0.40f, tint()},
            {{0.5f, 0.58f}, dir(49.0f), 0.39f, tint()},   {{0.5f, 0.79f}, dir(-63.0f), 0.38f, tint()},
            {{0.5f, 0.83f}, dir(61.0f), 0.37f, tint()}};
}

image_rgba8 broadleaf_leaf_texture(std::uint32_t size) {
    const std::vector<blade> blades = broadleaf_spray();
    return rasterise(size, [&](glm::vec2 p) {
        shape_sample best = capsule(p, {0.5f, 0.99f}, {0.5f, 0.34f}, 0.012f, k_twig_brown);
        for (const blade& b : blades) composite(best, leaf_blade(p, b));
        return best;
    });
}

struct needle {
    glm::vec2 a, b;
    glm::vec3 colour;
};

// Needles alternate left and right along the twig, angled 50-65 degrees towards the tip and
// shortening towards it, so the spray has the pointed outline of a fir shoot.
std::vector<needle> needle_spray() {
    rng random(k_texture_seed, 2);
    std::vector<needle> needles;
    const int count = 64;
    for (int i = 0; i < count; ++i) {
        const float t = (float(i) + 0.5f) / float(count);
        const float y = 0.96f - 0.82f * t;
        const float side = (i % 2 == 0) ? 1.0f : -1.0f;
        const float angle = random.uniform(50.0f, 65.0f) * k_pi / 180.0f;
        const float length = (0.40f - 0.24f * t) * random.uniform(0.85f, 1.05f);
        const glm::vec2 a{0.5f, y};
        const glm::vec2 b = a + glm::vec2(side * std::sin(angle), -std::cos(angle)) * length;
        needles.push_back({a, b, k_needle_green * random.uniform(0.8f, 1.25f)});
    }
    return needles;
}

image_rgba8 conifer_leaf_texture(std::uint32_t size) {
    const std::vector<needle> needles = needle_spray();
    return rasterise(size, [&](glm::vec2 p) {
        shape_sample best = capsule(p, {0.5f, 0.99f}, {0.5f, 0.1f}, 0.016f, k_twig_brown);
        for (const needle& n : needles) composite(best, capsule(p, n.a, n.b, 0.011f, n.colour));
        return best;
    });
}

// Bark: vertical furrows whose phase wanders with periodic fBm (so the furrows meander but the
// texture still tiles), plates lightened by fine value noise. `ridges` must be an integer count
// so u = 0 and u = 1 meet.
struct bark_style {
    int ridges;
    glm::vec3 plate;
    glm::vec3 furrow;
    float sharpness;
};

image_rgba8 bark_texture(std::uint32_t size, const bark_style& style) {
    image_rgba8 image = make_image(size);
    const fbm_settings wander{4, 2.0, 0.5f, 4};
    const fbm_settings grain{3, 2.0, 0.5f, 32};
    for (std::uint32_t y = 0; y < size; ++y) {
        for (std::uint32_t x = 0; x < size; ++x) {
            const glm::vec2 p = texel_centre(x, y, size);
            const float warp = 0.35f * fbm(double(p.x) * 4.0, double(p.y) * 4.0, k_texture_seed, wander);
            const float phase = float(style.ridges) * p.x + warp;
            const float ridge = std::pow(0.5f + 0.5f * std::cos(2.0f * k_pi * phase), style.sharpness);
            const float fine = fbm_value(double(p.x) * 32.0, double(p.y) * 32.0, k_texture_seed + 1, grain);
            const glm::vec3 c = style.furrow + (style.plate - style.furrow) * (1.0f - ridge);
            store(image, x, y, c * (0.75f + 0.5f * fine), 1.0f);
        }
    }
    return image;
}

}  // namespace

image_rgba8 generate_leaf_texture(std::string_view generator, std::uint32_t size) {
    require_generator(generator);
    return generator == "conifer" ? conifer_leaf_texture(size) : broadleaf_leaf_texture(size);
}

image_rgba8 generate_bark_texture(std::string_view generator, std::uint32_t size) {
    require_generator(generator);
    if (generator == "conifer") return bark_texture(size, {9, {0.20f, 0.12f, 0.08f}, {0.06f, 0.035f, 0.025f}, 3.0f});
    return bark_texture(size, {6, {0.22f, 0.20f, 0.17f}, {0.07f, 0.06f, 0.05f}, 6.0f});
}

image_rgba8 generate_ground_texture(std::uint32_t size) {
    image_rgba8 image = make_image(size);
    // Integer periods over the unit texture: every octave wraps at the texture edge.
    const fbm_settings patches{4, 2.0, 0.5f, 3};
    const fbm_settings blades{3, 2.0, 0.6f, 48};
    for (std::uint32_t y = 0; y < size; ++y) {
        for (std::uint32_t x = 0; x < size; ++x) {
            const glm::vec2 p = texel_centre(x, y, size);
            const float cover = fbm(double(p.x) * 3.0, double(p.y) * 3.0, k_texture_seed + 2, patches);
            const float grass = std::clamp(0.6f + 1.5f * cover, 0.0f, 1.0f);
            const float detail = fbm_value(double(p.x) * 48.0, double(p.y) * 48.0, k_texture_seed + 3, blades);
            const glm::vec3 c = k_soil + (k_grass - k_soil) * grass;
            store(image, x, y, c * (0.7f + 0.6f * detail), 1.0f);
        }
    }
    return image;
}

}  // namespace sylva
