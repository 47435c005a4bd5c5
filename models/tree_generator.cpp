#include "models/tree_generator.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "models/random.h"
#include "models/tree_skeleton.h"

namespace sylva {
namespace {

constexpr float k_pi = 3.14159265358979f;
constexpr float k_deg = k_pi / 180.0f;
constexpr glm::vec3 k_up{0.0f, 1.0f, 0.0f};
// Leaves start this far along their stem: the base of a twig is bare.
constexpr float k_leaf_start = 0.15f;
// Random scatter of leaf size and down angle around the species' values.
constexpr float k_leaf_size_variation = 0.15f;
constexpr float k_leaf_down_variation_deg = 12.0f;

struct mesh_builder {
    std::vector<vertex> vertices;
    std::vector<std::uint32_t> indices;
};

struct stem_resolution {
    int segments;
    int sides;
};

// What one detail level keeps of the full tree.
struct detail_profile {
    float leaf_quality = 1.0f;  // fraction of leaf cards kept, at constant total leaf area
    float segment_ratio = 1.0f;
    float sides_ratio = 1.0f;
    int bark_levels = 4;
};

detail_profile profile_for(const tree_params& p, tree_detail detail) {
    switch (detail) {
        case tree_detail::full: return {1.0f, 1.0f, 1.0f, p.levels};
        case tree_detail::reduced:
            return {p.reduced_leaf_quality, p.reduced_segment_ratio, p.reduced_sides_ratio,
                    std::min(p.levels - 1, p.reduced_bark_levels)};
        case tree_detail::far:
            return {p.far_leaf_quality, p.far_segment_ratio, p.far_sides_ratio, p.far_bark_levels};
    }
    return {};
}

stem_resolution resolution_for(const tree_params& p, int level, tree_detail detail) {
    const stem_level_params& lp = p.level[std::size_t(level)];
    if (detail == tree_detail::full) return {lp.segments, lp.sides};
    const detail_profile profile = profile_for(p, detail);
    return {std::max(1, static_cast<int>(std::lround(float(lp.segments) * profile.segment_ratio))),
            std::max(3, static_cast<int>(std::lround(float(lp.sides) * profile.sides_ratio)))};
}

// A generalized cylinder (W&P stems): one ring of sides + 1 vertices per segment end (the seam
// vertex repeats with u = 1), normals radial. v runs along the stem in units of the base
// circumference, so bark texels stay roughly square on every stem.
void add_stem(const stem& s, stem_resolution res, mesh_builder& out) {
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    const float circumference = std::max(2.0f * k_pi * s.nodes.front().radius, 1e-3f);
    const auto ring = static_cast<std::uint32_t>(res.sides + 1);
    for (int k = 0; k <= res.segments; ++k) {
        const float t = static_cast<float>(k) / static_cast<float>(res.segments);
        const stem_node node = sample_stem(s, t);
        const glm::vec3 binormal = glm::cross(node.tangent, node.normal);
        for (int j = 0; j <= res.sides; ++j) {
            const float u = static_cast<float>(j) / static_cast<float>(res.sides);
            const float angle = 2.0f * k_pi * u;
            const glm::vec3 radial = node.normal * std::cos(angle) + binormal * std::sin(angle);
            out.vertices.push_back({node.position + radial * node.radius, radial, {u, t * s.length / circumference}});
        }
    }
    for (int k = 0; k < res.segments; ++k) {
        for (int j = 0; j < res.sides; ++j) {
            const std::uint32_t a = base + static_cast<std::uint32_t>(k) * ring + static_cast<std::uint32_t>(j);
            const std::uint32_t b = a + ring;
            // Counter-clockwise seen from outside: around the ring, then along the stem.
            out.indices.insert(out.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
        }
    }
}

struct leaf_card {
    glm::vec3 base;  // where the leaf meets the twig
    glm::vec3 axis;  // unit, base to tip
    glm::vec3 side;  // unit, across the blade
    float length;
    float width;
};

// Broad leaves turn their blade to the sky (W&P orient leaves towards the light), rolled by a
// random tilt; needle sprays roll freely around their own axis, surrounding the twig.
glm::vec3 leaf_side(const tree_params& p, glm::vec3 axis, glm::vec3 fallback, rng& random) {
    glm::vec3 side = glm::cross(axis, k_up);
    side = glm::length(side) > 1e-3f ? glm::normalize(side) : fallback;
    const float roll = p.leaf == leaf_shape::needle_cluster ? random.uniform(0.0f, k_pi)
                                                            : random.vary(0.0f, p.leaf_tilt_variation_deg) * k_deg;
    // Rodrigues about axis; side is perpendicular to axis, so the parallel term vanishes.
    return glm::normalize(side * std::cos(roll) + glm::cross(axis, side) * std::sin(roll));
}

void add_leaf(const leaf_card& c, mesh_builder& out) {
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    const glm::vec3 normal = glm::normalize(glm::cross(c.side, c.axis));
    const glm::vec3 half = c.side * (0.5f * c.width);
    const glm::vec3 tip = c.axis * c.length;
    out.vertices.push_back({c.base - half, normal, {0.0f, 1.0f}});
    out.vertices.push_back({c.base + half, normal, {1.0f, 1.0f}});
    out.vertices.push_back({c.base + half + tip, normal, {1.0f, 0.0f}});
    out.vertices.push_back({c.base - half + tip, normal, {0.0f, 0.0f}});
    out.indices.insert(out.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

// W&P leaves per stem: Leaves * ShapeRatio(tapered cylindrical, offset / length_parent), so
// twigs near their parent's base carry fewer. `quality` < 1 keeps that fraction of the leaves
// at 1/sqrt(quality) the size (W&P "degradation at range"): the leaf area is unchanged. The
// kept count is rounded stochastically, so a twig may keep none and the expected area is exact.
void add_leaves(const tree_params& p, const tree_skeleton& tree, const stem& s, float quality, mesh_builder& out) {
    const stem& parent = tree.stems[std::size_t(std::max(s.parent, 0))];
    const float position = s.parent >= 0 ? s.offset_in_parent / parent.length : 1.0f;
    const float full = float(p.leaves_per_stem) * shape_ratio(crown_shape::tapered_cylindrical, position);
    const int full_count = std::max(1, static_cast<int>(std::lround(full)));
    rng random(hash_combine(s.seed, 2));
    const float kept = float(full_count) * quality + (quality < 1.0f ? random.uniform() : 0.0f);
    const int count = static_cast<int>(std::floor(kept));
    const float size_scale = 1.0f / std::sqrt(quality);
    float azimuth = random.uniform(0.0f, 2.0f * k_pi);
    for (int i = 0; i < count; ++i) {
        const float slot = (static_cast<float>(i) + random.uniform(0.25f, 0.75f)) / static_cast<float>(count);
        const stem_node node = sample_stem(s, k_leaf_start + (1.0f - k_leaf_start) * slot);
        azimuth += p.phyllotaxis_deg * k_deg;
        const glm::vec3 binormal = glm::cross(node.tangent, node.normal);
        const glm::vec3 radial = node.normal * std::cos(azimuth) + binormal * std::sin(azimuth);
        const float down = random.vary(p.leaf_down_angle_deg, k_leaf_down_variation_deg) * k_deg;
        const glm::vec3 axis = glm::normalize(node.tangent * std::cos(down) + radial * std::sin(down));
        const float nominal = p.leaf_length_m * random.vary(1.0f, k_leaf_size_variation);
        const float length = nominal * size_scale;
        // An enlarged card keeps the full-size leaf's tip and grows back towards the inside of
        // the crown, so the crown's outline does not swell when the renderer switches.
        const glm::vec3 base = node.position + radial * node.radius + axis * (nominal - length);
        const glm::vec3 fallback = glm::normalize(glm::cross(axis, radial));
        add_leaf({base, axis, leaf_side(p, axis, fallback, random), length, length * p.leaf_width_ratio}, out);
    }
}

void set_bounds(mesh_data& mesh) {
    if (mesh.vertices.empty()) return;
    mesh.bounds_min = mesh.bounds_max = mesh.vertices.front().position;
    for (const vertex& v : mesh.vertices) {
        mesh.bounds_min = glm::min(mesh.bounds_min, v.position);
        mesh.bounds_max = glm::max(mesh.bounds_max, v.position);
    }
}

mesh_data combine(mesh_builder&& bark, const mesh_builder& leaves) {
    mesh_data mesh;
    mesh.vertices = std::move(bark.vertices);
    mesh.indices = std::move(bark.indices);
    const auto bark_index_count = static_cast<std::uint32_t>(mesh.indices.size());
    const auto leaf_base = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), leaves.vertices.begin(), leaves.vertices.end());
    mesh.indices.reserve(mesh.indices.size() + leaves.indices.size());
    for (const std::uint32_t i : leaves.indices) mesh.indices.push_back(leaf_base + i);
    mesh.submeshes.push_back({0, bark_index_count, material_kind::bark});
    mesh.submeshes.push_back({bark_index_count, static_cast<std::uint32_t>(leaves.indices.size()), material_kind::leaf});
    set_bounds(mesh);
    return mesh;
}

}  // namespace

mesh_data generate_tree(const tree_params& params, std::uint64_t seed, tree_detail detail) {
    const tree_skeleton tree = build_tree_skeleton(params, seed);
    const int last_level = params.levels - 1;
    const detail_profile profile = profile_for(params, detail);
    const int bark_levels = std::min(params.bark_levels, profile.bark_levels);
    const float leaf_quality = std::clamp(profile.leaf_quality, 0.005f, 1.0f);
    mesh_builder bark;
    mesh_builder leaves;
    for (const stem& s : tree.stems) {
        // Stems finer than bark_levels (fewer at coarser detail) have no geometry but keep their
        // leaves where they were, so the crown silhouette does not change when the renderer
        // switches.
        if (s.level < bark_levels) add_stem(s, resolution_for(params, s.level, detail), bark);
        if (s.level == last_level) add_leaves(params, tree, s, leaf_quality, leaves);
    }
    return combine(std::move(bark), leaves);
}

}  // namespace sylva
