#include "models/generate/grass_generator.h"

#include <array>
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

struct blade_detail {
    int stride;    // keep every stride-th blade
    int segments;  // quads along a blade
};

blade_detail detail_for(tree_detail detail) {
    switch (detail) {
        case tree_detail::full: return {1, 4};
        case tree_detail::reduced: return {4, 2};
        case tree_detail::far: return {8, 1};
    }
    return {1, 4};
}

// One blade: rises from near the clump centre, leaning out, its lean growing along its length
// (a circular arc in the vertical plane through its azimuth), tapering towards the tip.
void add_blade(std::uint64_t seed, std::uint32_t index, blade_detail d, float width_scale, plant_mesh_builder& out) {
    rng random(hash_combine(seed, 1, index));
    const float azimuth = random.uniform(0.0f, 2.0f * k_pi);
    const glm::vec3 outward{std::cos(azimuth), 0.0f, std::sin(azimuth)};
    const glm::vec3 base = outward * (0.05f * std::sqrt(random.uniform()));
    const float length = random.uniform(0.35f, 0.7f);
    const float lean = random.uniform(5.0f, 25.0f) * k_deg;
    const float bend = random.uniform(15.0f, 50.0f) * k_deg;  // extra lean gained up to the tip
    const float half_width = random.uniform(0.004f, 0.007f) * width_scale;
    // Across the blade: horizontal, perpendicular to its lean, so it curves over its flat side.
    const glm::vec3 across = glm::normalize(glm::cross(outward, k_up));
    std::vector<glm::vec3> spine{base};
    std::vector<float> widths{half_width};
    std::vector<glm::vec3> sides{across};
    const float step = length / float(d.segments);
    for (int k = 1; k <= d.segments; ++k) {
        const float t = (float(k) - 0.5f) / float(d.segments);
        const float angle = lean + bend * t;
        spine.push_back(spine.back() + (k_up * std::cos(angle) + outward * std::sin(angle)) * step);
        widths.push_back(half_width * (1.0f - 0.5f * float(k) / float(d.segments)));
        sides.push_back(across);
    }
    const triangle_part part{index, 0, part_kind::blade, index};
    add_strip(out, spine, widths, sides, uv_rect{}, part);
    const glm::vec3 mid = spine[spine.size() / 2];
    const glm::vec3 along = glm::normalize(spine.back() - spine.front());
    out.leaves.push_back({mid, glm::normalize(glm::cross(across, along)), length, index, part_kind::blade});
}

}  // namespace

mesh_data generate_grass(std::uint64_t seed, tree_detail detail) {
    const blade_detail d = detail_for(detail);
    rng random(hash_combine(seed, 0));
    const auto blades = static_cast<std::uint32_t>(24 + random.below(13));  // 24..36
    const auto stride = static_cast<std::uint32_t>(d.stride);
    const std::uint32_t kept = (blades + stride - 1) / stride;
    // The kept blades widen to the blade area of the whole tuft.
    const float width_scale = float(blades) / float(kept);
    plant_mesh_builder foliage;
    for (std::uint32_t i = 0; i < blades; i += stride) add_blade(seed, i, d, width_scale, foliage);
    return assemble_plant_mesh({}, std::move(foliage));
}

}  // namespace sylva
