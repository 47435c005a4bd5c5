#include "models/bake/point_sampling.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <glm/geometric.hpp>

#include "models/bake/implicit_illumination.h"
#include "models/image/texture_sampling.h"

namespace sylva {
namespace {

// Rejection tries before falling back to a known-opaque cell centre.
constexpr int k_rejection_tries = 8;
constexpr float k_alpha_threshold = 0.5f;
constexpr glm::vec3 k_untextured_colour{0.5f};
constexpr float k_tail_fraction = 0.05f;  // dropped at either end of the area ratio test


bool has_texels(const image_rgba8* texture) {
    return texture != nullptr && texture->width > 0 && texture->height > 0 &&
           texture->texels.size() >= std::size_t(texture->width) * texture->height * 4;
}

// Uniform in the triangle a, b, c (the square folded along its diagonal).
glm::vec2 uniform_in(const barycentric_region& r, rng& random) {
    float s = random.uniform();
    float t = random.uniform();
    if (s + t > 1.0f) {
        s = 1.0f - s;
        t = 1.0f - t;
    }
    return r.corner[0] + s * (r.corner[1] - r.corner[0]) + t * (r.corner[2] - r.corner[0]);
}

float cross2(glm::vec2 a, glm::vec2 b) {
    return a.x * b.y - a.y * b.x;
}

bool inside(const barycentric_region& r, glm::vec2 p) {
    const float d0 = cross2(r.corner[1] - r.corner[0], p - r.corner[0]);
    const float d1 = cross2(r.corner[2] - r.corner[1], p - r.corner[1]);
    const float d2 = cross2(r.corner[0] - r.corner[2], p - r.corner[2]);
    return (d0 >= 0.0f && d1 >= 0.0f && d2 >= 0.0f) || (d0 <= 0.0f && d1 <= 0.0f && d2 <= 0.0f);
}

// The k-th set bit of `bits` (k < popcount).
int nth_bit(std::uint64_t bits, std::uint32_t k) {
    for (; k > 0; --k) bits &= bits - 1;
    return std::countr_zero(bits);
}

}  // namespace

surface_texture surface_of(material_kind material, const image_rgba8& leaf_texture,
                           const image_rgba8& bark_texture) {
    switch (material) {
        case material_kind::leaf:
        case material_kind::billboard:
        case material_kind::facing_billboard:
        case material_kind::billboard_cloud:
            return {&leaf_texture, true};
        case material_kind::bark:
        case material_kind::ground:
            return {&bark_texture, false};
    }
    return {&bark_texture, false};
}

float texture_alpha(const image_rgba8& texture, glm::vec2 uv) { return bilinear_alpha(texture, uv) / 255.0f; }

glm::vec3 texture_colour(const image_rgba8& texture, glm::vec2 uv, bool alpha_weighted) {
    return bilinear_colour(texture, uv, alpha_weighted) / 255.0f;
}

bool passes_alpha_test(const surface_texture& surface, glm::vec2 uv) {
    if (!surface.alpha_tested || !has_texels(surface.texture)) return true;
    return texture_alpha(*surface.texture, uv) >= k_alpha_threshold;
}

// Cells in rows of constant b2 (j): the upward cells (i, j), i + j < m, have corners
// (i, j), (i+1, j), (i, j+1) in units of 1/m; the downward ones, i + j < m - 1, have corners
// (i+1, j), (i+1, j+1), (i, j+1). m² cells of area 1/m² of the triangle each.
glm::vec2 coverage_cell_centre(int cell) {
    constexpr int m = k_coverage_subdivision;
    int c = cell;
    for (int j = 0; j < m; ++j) {
        const int up = m - j;
        const int down = m - j - 1;
        if (c < up)
            return {(float(c) + 1.0f / 3.0f) / float(m), (float(j) + 1.0f / 3.0f) / float(m)};
        c -= up;
        if (c < down)
            return {(float(c) + 2.0f / 3.0f) / float(m), (float(j) + 2.0f / 3.0f) / float(m)};
        c -= down;
    }
    return {1.0f / 3.0f, 1.0f / 3.0f};
}

vertex point_at(const triangle_corners& t, glm::vec2 b) {
    const float b0 = 1.0f - b.x - b.y;
    vertex out;
    out.position = b0 * t.v[0].position + b.x * t.v[1].position + b.y * t.v[2].position;
    out.uv = b0 * t.v[0].uv + b.x * t.v[1].uv + b.y * t.v[2].uv;
    const glm::vec3 n = b0 * t.v[0].normal + b.x * t.v[1].normal + b.y * t.v[2].normal;
    const float length = glm::length(n);
    if (length > 1e-6f) {
        // A unit direction times the corners' own lengths interpolated: 1 for plain normals, and
        // Luft 2007's k_a where the model carries it (models/bake/implicit_illumination.h).
        const bool ambient = carries_ambient(t.v[0]) || carries_ambient(t.v[1]) || carries_ambient(t.v[2]);
        out.normal = !ambient ? n / length
                              : n / length * (b0 * glm::length(t.v[0].normal) + b.x * glm::length(t.v[1].normal) +
                                              b.y * glm::length(t.v[2].normal));
    } else {
        const glm::vec3 g =
            glm::cross(t.v[1].position - t.v[0].position, t.v[2].position - t.v[0].position);
        const float g_length = glm::length(g);
        out.normal = g_length > 0.0f ? g / g_length : glm::vec3{0.0f, 1.0f, 0.0f};
    }
    return out;
}

float triangle_area(const triangle_corners& t) {
    return 0.5f * glm::length(glm::cross(t.v[1].position - t.v[0].position,
                                         t.v[2].position - t.v[0].position));
}

// Deussen 2002 §4.1 "equal surfaces receive equal numbers of points": with cut-away texels the
// surface is only the part that survives the alpha test, so that is what the area counts.
triangle_coverage measure_coverage(const triangle_corners& corners,
                                   const surface_texture& surface) {
    triangle_coverage out;
    out.area = triangle_area(corners);
    const bool textured = has_texels(surface.texture);
    glm::vec3 colour{0.0f};
    glm::vec3 centroid{0.0f};
    int opaque = 0;
    for (int c = 0; c < k_coverage_cells; ++c) {
        const glm::vec2 b = coverage_cell_centre(c);
        const vertex p = point_at(corners, b);
        if (!passes_alpha_test(surface, p.uv)) continue;
        out.opaque_cells |= std::uint64_t(1) << c;
        colour += textured ? texture_colour(*surface.texture, p.uv, surface.alpha_tested)
                           : k_untextured_colour;
        centroid += p.position;
        ++opaque;
    }
    if (opaque > 0) {
        out.colour = colour / float(opaque);
        out.opaque_centroid = centroid / float(opaque);
    }
    out.opaque_area = out.area * float(opaque) / float(k_coverage_cells);
    return out;
}

std::array<barycentric_region, 2> triangle_halves(const triangle_corners& t) {
    constexpr std::array<glm::vec2, 3> k_corner{glm::vec2{0.0f, 0.0f}, glm::vec2{1.0f, 0.0f},
                                                glm::vec2{0.0f, 1.0f}};
    // Corner k faces the edge between the other two; pick the k whose opposite edge is longest.
    int apex = 0;
    float longest = -1.0f;
    for (int k = 0; k < 3; ++k) {
        const glm::vec3 e =
            t.v[std::size_t((k + 2) % 3)].position - t.v[std::size_t((k + 1) % 3)].position;
        const float length = glm::dot(e, e);
        if (length > longest) {
            longest = length;
            apex = k;
        }
    }
    const glm::vec2 a = k_corner[std::size_t(apex)];
    const glm::vec2 b = k_corner[std::size_t((apex + 1) % 3)];
    const glm::vec2 c = k_corner[std::size_t((apex + 2) % 3)];
    const glm::vec2 mid = 0.5f * (b + c);
    return {barycentric_region{{a, b, mid}}, barycentric_region{{a, mid, c}}};
}

vertex sample_opaque_point(const triangle_corners& corners, const triangle_coverage& coverage,
                           const surface_texture& surface, const barycentric_region& region,
                           rng& random) {
    vertex last;
    for (int attempt = 0; attempt < k_rejection_tries; ++attempt) {
        last = point_at(corners, uniform_in(region, random));
        if (passes_alpha_test(surface, last.uv)) return last;
    }
    if (coverage.opaque_cells == 0) return last;
    std::uint64_t in_region = 0;
    for (std::uint64_t bits = coverage.opaque_cells; bits != 0; bits &= bits - 1) {
        const int c = std::countr_zero(bits);
        if (inside(region, coverage_cell_centre(c))) in_region |= std::uint64_t(1) << c;
    }
    const std::uint64_t choices = in_region != 0 ? in_region : coverage.opaque_cells;
    const int cell = nth_bit(choices, random.below(std::uint32_t(std::popcount(choices))));
    return point_at(corners, coverage_cell_centre(cell));
}

bool similar_areas(std::span<const float> areas, float ratio) {
    std::vector<float> sorted(areas.begin(), areas.end());
    std::sort(sorted.begin(), sorted.end());
    const auto tail = std::size_t(k_tail_fraction * float(sorted.size()));
    return sorted[sorted.size() - 1 - tail] < ratio * sorted[tail];
}

std::vector<std::uint32_t> area_weighted_counts(std::span<const float> areas, rng& random) {
    const std::size_t total = 2 * areas.size();
    double sum = 0.0;
    for (const float a : areas) sum += a;
    const double step = sum / double(total);
    const double offset = random.uniform_double();
    std::vector<std::uint32_t> counts(areas.size(), 0);
    std::size_t k = 0;
    double cumulative = 0.0;
    std::size_t last = 0;
    for (std::size_t i = 0; i < areas.size(); ++i) {
        cumulative += areas[i];
        if (areas[i] > 0.0f) last = i;
        for (; k < total && (double(k) + offset) * step < cumulative; ++k) ++counts[i];
    }
    for (; k < total; ++k) ++counts[last];  // rounding at the very end of the sum
    return counts;
}

}  // namespace sylva
