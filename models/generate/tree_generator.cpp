#include "models/generate/tree_generator.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "models/generate/plant_mesh_builder.h"
#include "models/random.h"
#include "models/generate/tree_skeleton.h"

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

// A W&P stem as a tube (see add_tube); v runs along the stem in units of the base circumference,
// so bark texels stay roughly square on every stem.
void add_stem(const tree_skeleton& tree, std::size_t index, stem_resolution res, plant_mesh_builder& out) {
    const stem& s = tree.stems[index];
    const float circumference = std::max(2.0f * k_pi * s.nodes.front().radius, 1e-3f);
    std::vector<tube_ring> rings;
    rings.reserve(std::size_t(res.segments) + 1);
    for (int k = 0; k <= res.segments; ++k) {
        const stem_node node = sample_stem(s, static_cast<float>(k) / static_cast<float>(res.segments));
        rings.push_back({node.position, node.tangent, node.normal, node.radius});
    }
    const auto id = static_cast<std::uint32_t>(index);
    const auto parent = s.parent >= 0 ? static_cast<std::uint32_t>(s.parent) : id;
    add_tube(out, rings, res.sides, circumference, {id, static_cast<std::uint8_t>(s.level), part_kind::bark, parent});
}

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

// W&P leaves per stem: Leaves * ShapeRatio(tapered cylindrical, offset / length_parent), so
// twigs near their parent's base carry fewer. `quality` < 1 keeps that fraction of the leaves
// at 1/sqrt(quality) the size (W&P "degradation at range"): the leaf area is unchanged. The
// kept count is rounded stochastically, so a twig may keep none and the expected area is exact.
void add_leaves(const tree_params& p, const tree_skeleton& tree, std::size_t index, float quality, plant_mesh_builder& out) {
    const stem& s = tree.stems[index];
    const auto id = static_cast<std::uint32_t>(index);
    const part_kind kind = p.leaf == leaf_shape::needle_cluster ? part_kind::needle : part_kind::leaf;
    // parent_branch is the parent of the carrying stem, as on that stem's bark: the twigs of the
    // last level often have no bark (bark_levels), and this is then their only link to the
    // branch they grow on (hierarchy-aware billboard-cloud clustering walks it).
    const auto stem_parent = s.parent >= 0 ? static_cast<std::uint32_t>(s.parent) : id;
    const triangle_part part{id, static_cast<std::uint8_t>(s.level + 1), kind, stem_parent};
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
        const card c{base, axis, leaf_side(p, axis, fallback, random), length, length * p.leaf_width_ratio};
        add_card(out, c, uv_rect{}, part);
        out.leaves.push_back(card_record(c, id, kind));
    }
}

}  // namespace

mesh_data generate_tree(const tree_params& params, std::uint64_t seed, tree_detail detail) {
    const tree_skeleton tree = build_tree_skeleton(params, seed);
    const int last_level = params.levels - 1;
    const detail_profile profile = profile_for(params, detail);
    const int bark_levels = std::min(params.bark_levels, profile.bark_levels);
    const float leaf_quality = std::clamp(profile.leaf_quality, 0.005f, 1.0f);
    plant_mesh_builder bark;
    plant_mesh_builder leaves;
    for (std::size_t i = 0; i < tree.stems.size(); ++i) {
        const stem& s = tree.stems[i];
        // Stems finer than bark_levels (fewer at coarser detail) have no geometry but keep their
        // leaves where they were, so the crown silhouette does not change when the renderer
        // switches.
        if (s.level < bark_levels) add_stem(tree, i, resolution_for(params, s.level, detail), bark);
        if (s.level == last_level) add_leaves(params, tree, i, leaf_quality, leaves);
    }
    return assemble_plant_mesh(std::move(bark), std::move(leaves));
}

}  // namespace sylva
