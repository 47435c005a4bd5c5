#include "models/generate/textures.h"

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
#include "models/generate/texture_paint.h"
#include "models/generate/tree_params.h"

namespace sylva {
namespace {

using namespace texture_paint;

constexpr std::uint64_t k_texture_seed = 0x7e47u;

// Linear albedos (roughly measured ranges: green leaves reflect 5-15% in the visible, bark and
// soil 10-25%), so the renderer's lighting, not the texture, sets the brightness.
constexpr glm::vec3 k_needle_green{0.020f, 0.060f, 0.014f};
constexpr glm::vec3 k_twig_brown{0.07f, 0.045f, 0.028f};
constexpr glm::vec3 k_grass{0.07f, 0.15f, 0.035f};
constexpr glm::vec3 k_soil{0.16f, 0.11f, 0.06f};

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
    const glm::vec3 lit = glm::vec3(0.08f, 0.16f, 0.04f);
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

// A leafy twig seen from above: about two dozen overlapping ovate leaves on a central twig and
// its side shoots, filling an ovoid with ~60% cover, so a card reads as a clump of foliage and
// keeps its outline in the coarse mip levels (the renderer alpha-tests at 0.5).
std::vector<blade> broadleaf_spray() {
    rng random(k_texture_seed, 1);
    auto tint = [&] { return k_leaf_green * glm::vec3(random.uniform(0.8f, 1.2f), random.uniform(0.8f, 1.2f), 1.0f); };
    auto dir = [](float deg) { return glm::vec2(std::sin(deg * k_pi / 180.0f), -std::cos(deg * k_pi / 180.0f)); };
    std::vector<blade> blades;
    // Terminal leaves at the tip of the twig.
    blades.push_back({{0.5f, 0.30f}, dir(random.uniform(-8.0f, 8.0f)), 0.26f, tint()});
    blades.push_back({{0.5f, 0.34f}, dir(-28.0f), 0.26f, tint()});
    blades.push_back({{0.5f, 0.35f}, dir(30.0f), 0.26f, tint()});
    const int pairs = 11;
    for (int i = 0; i < pairs; ++i) {
        const float t = (float(i) + 0.5f) / float(pairs);  // 0 at the stalk, 1 near the tip
        const float y = 0.86f - 0.50f * t;
        for (const float side : {-1.0f, 1.0f}) {
            const float angle = side * (random.uniform(40.0f, 95.0f) - 25.0f * t);
            const float length = random.uniform(0.30f, 0.38f) * (1.0f - 0.25f * t);
            const glm::vec2 base{0.5f + side * random.uniform(0.0f, 0.06f), y + random.uniform(-0.03f, 0.03f)};
            blades.push_back({base, dir(angle), length, tint()});
        }
    }
    // Leaves of the side shoots, filling the ovoid around the twig: each points away from the
    // clump's centre, so the outline is leaf tips all round.
    const glm::vec2 centre{0.5f, 0.55f};
    for (int i = 0; i < 22; ++i) {
        const float a = random.uniform(0.0f, 2.0f * k_pi);
        const float r = std::sqrt(random.uniform(0.15f, 1.0f));
        const glm::vec2 base = centre + glm::vec2(std::cos(a) * 0.22f, std::sin(a) * 0.26f) * r;
        const glm::vec2 out = glm::normalize(base - centre + glm::vec2(0.0f, -0.05f));
        const float turn = random.uniform(-0.4f, 0.4f);
        const glm::vec2 axis{out.x * std::cos(turn) - out.y * std::sin(turn), out.x * std::sin(turn) + out.y * std::cos(turn)};
        blades.push_back({base, axis, random.uniform(0.2f, 0.28f), tint()});
    }
    // Keep every blade (tip and widest part) inside a clear border, so clamped sampling and the
    // mip chain never smear leaf into the card's edge.
    for (blade& b : blades) {
        const glm::vec2 perp{-b.axis.y, b.axis.x};
        for (int k = 0; k < 16; ++k) {
            bool inside = true;
            for (const float s : {0.35f, 0.7f, 1.0f}) {
                const float half = ovate_half_width(s) * b.length;
                for (const float w : {-half, half}) {
                    const glm::vec2 q = b.base + b.axis * (s * b.length) + perp * w;
                    inside = inside && q.x > 0.04f && q.x < 0.96f && q.y > 0.04f && q.y < 0.96f;
                }
            }
            if (inside) break;
            b.length *= 0.92f;
        }
    }
    return blades;
}

image_rgba8 broadleaf_leaf_texture(std::uint32_t size) {
    const std::vector<blade> blades = broadleaf_spray();
    return rasterise(size, [&](glm::vec2 p) {
        shape_sample best = capsule(p, {0.5f, 0.97f}, {0.5f, 0.4f}, 0.01f, k_twig_brown);
        for (const blade& b : blades) composite(best, leaf_blade(p, b));
        return best;
    });
}

struct needle {
    glm::vec2 a, b;
    glm::vec3 colour;
};

// A spruce shoot: a main twig with side shoots angled towards the tip, every shoot densely
// set with short needles on both sides (and some pointing at the viewer, seen as short
// strokes), shoots shortening towards the tip so the spray has a pointed ovoid outline. Dense
// enough (~60% cover) that the card keeps its outline in the coarse mip levels.
std::vector<needle> needle_spray() {
    rng random(k_texture_seed, 2);
    std::vector<needle> needles;
    auto add_shoot = [&](glm::vec2 from, glm::vec2 to, float needle_length) {
        const glm::vec2 along = to - from;
        const float length = glm::length(along);
        const glm::vec2 axis = along / length;
        const glm::vec2 perp{-axis.y, axis.x};
        const int count = std::max(4, static_cast<int>(length / 0.011f));
        for (int i = 0; i < count; ++i) {
            const float t = (float(i) + random.uniform(0.2f, 0.8f)) / float(count);
            const glm::vec2 a = from + along * t;
            const float side = (i % 2 == 0) ? 1.0f : -1.0f;
            const float angle = random.uniform(35.0f, 70.0f) * k_pi / 180.0f;
            const float l = needle_length * (1.0f - 0.35f * t) * random.uniform(0.8f, 1.1f);
            const glm::vec2 d = axis * std::cos(angle) + perp * (side * std::sin(angle));
            needles.push_back({a, a + d * l, k_needle_green * random.uniform(0.75f, 1.3f)});
            if (i % 3 == 0) {  // a needle towards the viewer: foreshortened, along the shoot
                const glm::vec2 q = a + perp * random.uniform(-0.3f, 0.3f) * l;
                needles.push_back({q, q + axis * (0.4f * l), k_needle_green * random.uniform(0.9f, 1.4f)});
            }
        }
    };
    const glm::vec2 stalk{0.5f, 0.95f};
    const glm::vec2 tip{0.5f, 0.07f};
    add_shoot(stalk, tip, 0.09f);
    const int shoots = 7;
    for (int i = 0; i < shoots; ++i) {
        const float t = (float(i) + 0.5f) / float(shoots);
        const glm::vec2 from = stalk + (tip - stalk) * (0.08f + 0.8f * t);
        for (const float side : {-1.0f, 1.0f}) {
            const float angle = random.uniform(45.0f, 60.0f) * k_pi / 180.0f;
            const float length = (0.44f - 0.34f * t) * random.uniform(0.85f, 1.05f);
            const glm::vec2 to = from + glm::vec2(side * std::sin(angle), -std::cos(angle)) * length;
            add_shoot(from, to, 0.08f);
        }
    }
    return needles;
}

image_rgba8 conifer_leaf_texture(std::uint32_t size) {
    const std::vector<needle> needles = needle_spray();
    return rasterise(size, [&](glm::vec2 p) {
        shape_sample best = capsule(p, {0.5f, 0.97f}, {0.5f, 0.1f}, 0.008f, k_twig_brown);
        for (const needle& n : needles) composite(best, capsule(p, n.a, n.b, 0.01f, n.colour));
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
    if (generator == "conifer") return bark_texture(size, {9, {0.09f, 0.052f, 0.036f}, {0.022f, 0.015f, 0.011f}, 3.0f});
    return bark_texture(size, {6, {0.11f, 0.095f, 0.075f}, {0.028f, 0.024f, 0.020f}, 6.0f});
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
