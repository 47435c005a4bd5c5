#include "models/generate/fern_generator.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "models/generate/plant_mesh_builder.h"
#include "models/random.h"

namespace sylva {
namespace {

constexpr float k_pi = 3.14159265358979f;
constexpr float k_deg = k_pi / 180.0f;
constexpr glm::vec3 k_up{0.0f, 1.0f, 0.0f};
constexpr int k_rachis_segments = 9;
constexpr int k_full_pairs = 16;
constexpr float k_pinna_width_ratio = 0.3f;
constexpr float k_pinnae_start = 0.15f;  // the bare stipe below the first pinnae

struct frond {
    std::vector<tube_ring> rachis;
    glm::vec3 side;  // horizontal, across the frond
    float length;
    float pinna_length;
};

// The rachis rises steeply, then arches over and down (a circular-ish arc in its plane).
frond make_frond(std::uint64_t seed, std::uint32_t index, std::uint32_t count) {
    rng random(hash_combine(seed, 1, index));
    const float azimuth = 2.0f * k_pi * (float(index) + random.uniform(-0.3f, 0.3f)) / float(count);
    const glm::vec3 outward{std::cos(azimuth), 0.0f, std::sin(azimuth)};
    frond f;
    f.side = glm::normalize(glm::cross(outward, k_up));
    f.length = random.uniform(0.6f, 0.95f);
    f.pinna_length = f.length * random.uniform(0.16f, 0.2f);
    const float rise = random.uniform(55.0f, 75.0f) * k_deg;  // above the horizontal
    const float arch = random.uniform(60.0f, 90.0f) * k_deg;
    glm::vec3 p = outward * 0.03f;
    const float step = f.length / float(k_rachis_segments);
    for (int k = 0; k <= k_rachis_segments; ++k) {
        const float t = float(k) / float(k_rachis_segments);
        const float angle = rise - arch * t;
        const glm::vec3 tangent = outward * std::cos(angle) + k_up * std::sin(angle);
        f.rachis.push_back({p, tangent, f.side, 0.004f * (1.0f - 0.7f * t)});
        p += tangent * step;
    }
    return f;
}

tube_ring rachis_at(const frond& f, float t) {
    const float x = t * float(k_rachis_segments);
    const auto i = std::min(static_cast<std::size_t>(x), std::size_t(k_rachis_segments - 1));
    const float a = x - float(i);
    const tube_ring& r0 = f.rachis[i];
    const tube_ring& r1 = f.rachis[i + 1];
    return {r0.position + (r1.position - r0.position) * a, glm::normalize(r0.tangent + (r1.tangent - r0.tangent) * a),
            f.side, r0.radius + (r1.radius - r0.radius) * a};
}

// Pinna length along the frond: longest a third of the way up, short at both ends (the
// lanceolate outline of a male fern's blade).
float pinna_profile(float s) { return std::sin(k_pi * std::pow(s, 0.7f)) * 0.9f + 0.1f; }

// `pairs` pairs of pinnae, enlarged so their area equals that of the full k_full_pairs pairs.
void add_pinnae(const frond& f, std::uint32_t index, int pairs, plant_mesh_builder& out) {
    float full_area = 0.0f;
    for (int i = 0; i < k_full_pairs; ++i) full_area += std::pow(pinna_profile((float(i) + 0.5f) / k_full_pairs), 2.0f);
    float area = 0.0f;
    for (int i = 0; i < pairs; ++i) area += std::pow(pinna_profile((float(i) + 0.5f) / float(pairs)), 2.0f);
    const float scale = std::sqrt(full_area / area);
    const triangle_part part{index, 1, part_kind::frond, index};
    for (int i = 0; i < pairs; ++i) {
        const float s = (float(i) + 0.5f) / float(pairs);
        const tube_ring at = rachis_at(f, k_pinnae_start + (1.0f - k_pinnae_start) * s);
        const glm::vec3 frond_normal = glm::normalize(glm::cross(f.side, at.tangent));
        const float length = f.pinna_length * pinna_profile(s) * scale;
        for (const float sign : {-1.0f, 1.0f}) {
            // Pinnae sweep forward, 60 degrees from the rachis, in the frond's plane.
            const glm::vec3 axis = glm::normalize(f.side * (sign * std::sin(60.0f * k_deg)) + at.tangent * std::cos(60.0f * k_deg));
            const card c{at.position, axis, glm::normalize(glm::cross(axis, frond_normal)), length, length * k_pinna_width_ratio};
            add_card(out, c, uv_rect{}, part);
            out.leaves.push_back(card_record(c, index, part_kind::frond));
        }
    }
}

// Far detail: the frond's whole blade as one strip along the rachis (the pinna texture's
// lanceolate, lobed outline reads as a frond at a distance), as wide as the full pinnae's area.
void add_frond_card(const frond& f, std::uint32_t index, plant_mesh_builder& out) {
    float full_area = 0.0f;
    for (int i = 0; i < k_full_pairs; ++i) full_area += std::pow(pinna_profile((float(i) + 0.5f) / k_full_pairs), 2.0f);
    full_area *= 2.0f * f.pinna_length * f.pinna_length * k_pinna_width_ratio;
    const float length = f.length * (1.0f - k_pinnae_start);
    const float half_width = 0.5f * full_area / length;
    std::vector<glm::vec3> spine;
    for (const float t : {0.0f, 0.5f, 1.0f}) spine.push_back(rachis_at(f, k_pinnae_start + (1.0f - k_pinnae_start) * t).position);
    const std::vector<float> widths(3, half_width);
    const std::vector<glm::vec3> sides(3, f.side);
    add_strip(out, spine, widths, sides, uv_rect{}, {index, 1, part_kind::frond, index});
    const glm::vec3 along = glm::normalize(spine.back() - spine.front());
    out.leaves.push_back({spine[1], glm::normalize(glm::cross(f.side, along)), length, index, part_kind::frond});
}

}  // namespace

mesh_data generate_fern(std::uint64_t seed, tree_detail detail) {
    rng random(hash_combine(seed, 0));
    const auto count = static_cast<std::uint32_t>(9 + random.below(5));  // 9..13 fronds
    plant_mesh_builder bark;
    plant_mesh_builder foliage;
    for (std::uint32_t i = 0; i < count; ++i) {
        const frond f = make_frond(seed, i, count);
        if (detail == tree_detail::full) {
            add_tube(bark, f.rachis, 3, 0.03f, {i, 0, part_kind::bark, i});
            add_pinnae(f, i, k_full_pairs, foliage);
        } else if (detail == tree_detail::reduced) {
            add_pinnae(f, i, 3, foliage);
        } else {
            add_frond_card(f, i, foliage);
        }
    }
    return assemble_plant_mesh(std::move(bark), std::move(foliage));
}

}  // namespace sylva
