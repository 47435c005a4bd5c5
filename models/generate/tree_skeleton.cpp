#include "models/generate/tree_skeleton.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

#include "models/random.h"

namespace sylva {
namespace {

constexpr float k_pi = 3.14159265358979f;
constexpr float k_deg = k_pi / 180.0f;
constexpr glm::vec3 k_up{0.0f, 1.0f, 0.0f};
// Tips keep a little radius so taper 1 does not collapse the last ring into degenerate triangles.
constexpr float k_min_tip_radius_fraction = 0.08f;
// A child may not be thicker than this fraction of its parent where it attaches.
constexpr float k_max_child_radius_fraction = 0.9f;

// Rodrigues' rotation of v about the unit axis.
glm::vec3 rotate(glm::vec3 v, glm::vec3 axis, float angle) {
    const float c = std::cos(angle);
    const float s = std::sin(angle);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0f - c);
}

// Any unit vector perpendicular to the unit vector t.
glm::vec3 perpendicular(glm::vec3 t) {
    const glm::vec3 helper = std::abs(t.y) < 0.9f ? k_up : glm::vec3(1.0f, 0.0f, 0.0f);
    return glm::normalize(glm::cross(helper, t));
}

// Gram-Schmidt: n made perpendicular to unit t, unit length (fallback if they were parallel).
glm::vec3 orthonormal(glm::vec3 n, glm::vec3 t) {
    const glm::vec3 p = n - t * glm::dot(n, t);
    const float len = glm::length(p);
    return len > 1e-6f ? p / len : perpendicular(t);
}

// W&P stem radius along the stem: linear taper (nTaper in 0..1), and for the trunk the flare
// flare_z = Flare * (100^y - 1) / 100 + 1 with y = max(0, 1 - 8z).
float radius_at(float base, float taper, float flare, float z) {
    float r = base * std::max(1.0f - taper * z, k_min_tip_radius_fraction);
    if (flare > 0.0f) {
        const float y = std::max(0.0f, 1.0f - 8.0f * z);
        r *= flare * (std::pow(100.0f, y) - 1.0f) / 100.0f + 1.0f;
    }
    return r;
}

// Bend of segment joint i (W&P nCurve / nCurveBack / nCurveV spread over nCurveRes segments).
float joint_bend(const stem_level_params& lp, int i, rng& random) {
    const auto segments = static_cast<float>(lp.segments);
    float bend = lp.curve_deg / segments;
    if (lp.curve_back_deg != 0.0f)
        bend = (2 * i < lp.segments ? lp.curve_deg : lp.curve_back_deg) / std::max(1.0f, 0.5f * segments);
    return (bend + random.vary(0.0f, lp.curve_variation_deg / segments)) * k_deg;
}

// W&P vertical attraction: curve_up = AttractionUp * |declination * sin(declination)| / nCurveRes,
// turning the stem towards the sky (negative attraction: towards the ground).
float attraction_bend(float attraction, glm::vec3 direction, int segments) {
    const float declination = std::acos(std::clamp(direction.y, -1.0f, 1.0f));
    return attraction * std::abs(declination * std::sin(declination)) / static_cast<float>(segments);
}

struct stem_start {
    glm::vec3 position;
    glm::vec3 direction;
    glm::vec3 normal;
    float length;
    float radius;
};

// Walks the stem segment by segment, bending at each joint about an axis that makes positive
// nCurve turn the stem upwards; the normal is rotated with it (parallel transport).
std::vector<stem_node> trace_path(const tree_params& params, int level, const stem_start& start, rng& random) {
    const stem_level_params& lp = params.level[std::size_t(level)];
    const int segments = lp.segments;
    const float segment_length = start.length / static_cast<float>(segments);
    const float attraction = level >= 2 ? params.attraction_up : 0.0f;  // W&P: not trunk, not level 1
    glm::vec3 bend_axis = glm::cross(start.direction, k_up);
    bend_axis = glm::length(bend_axis) > 1e-4f ? glm::normalize(bend_axis) : glm::cross(start.direction, start.normal);

    std::vector<glm::vec3> directions{start.direction};
    std::vector<glm::vec3> normals{start.normal};
    for (int i = 1; i < segments; ++i) {
        const glm::vec3 d = directions.back();
        const glm::vec3 axis = orthonormal(bend_axis, d);
        const float angle = joint_bend(lp, i, random) + attraction_bend(attraction, d, segments);
        directions.push_back(glm::normalize(rotate(d, axis, angle)));
        normals.push_back(orthonormal(rotate(normals.back(), axis, angle), directions.back()));
    }

    std::vector<stem_node> nodes(std::size_t(segments) + 1);
    glm::vec3 p = start.position;
    const float flare = level == 0 ? params.flare : 0.0f;
    for (int i = 0; i <= segments; ++i) {
        const auto k = std::size_t(i);
        const std::size_t before = std::min(k, std::size_t(segments - 1));
        const std::size_t after = k > 0 ? k - 1 : 0;
        stem_node& n = nodes[k];
        n.position = p;
        n.tangent = glm::normalize(directions[before] + directions[after]);
        n.normal = orthonormal(normals[before], n.tangent);
        n.radius = radius_at(start.radius, lp.taper, flare, static_cast<float>(i) / static_cast<float>(segments));
        if (i < segments) p += directions[k] * segment_length;
    }
    return nodes;
}

// W&P child counts: all nBranches on the trunk; deeper, scaled by the parent's relative length
// stems = nBranches * (0.2 + 0.8 * (length_parent / length_grandparent) / nLength_parent).
int child_count(const tree_params& params, const tree_skeleton& tree, const stem& parent) {
    const stem_level_params& child_level = params.level[std::size_t(parent.level + 1)];
    if (parent.parent < 0) return child_level.branches;
    const stem& grandparent = tree.stems[std::size_t(parent.parent)];
    const float max_ratio = params.level[std::size_t(parent.level)].length;
    const float relative = (parent.length / grandparent.length) / max_ratio;
    return static_cast<int>(std::lround(float(child_level.branches) * (0.2f + 0.8f * relative)));
}

// W&P child length: on the trunk shaped by the crown, deeper proportional to the parent's
// remaining length: nLength * (length_parent - 0.6 * offset_child).
float child_length(const tree_params& params, const stem& parent, float offset, float max_ratio) {
    if (parent.parent >= 0) return max_ratio * (parent.length - 0.6f * offset);
    const float base_length = params.base_size * parent.length;
    const float ratio = (parent.length - offset) / std::max(parent.length - base_length, 1e-4f);
    return parent.length * max_ratio * shape_ratio(params.shape, ratio);
}

// W&P down angle: nDownAngle ± nDownAngleV, or for a negative nDownAngleV a deterministic spread
// along the parent, nDownAngle + nDownAngleV * (1 - 2 * ShapeRatio(conical, ratio)): children
// near the base point further down than those near the top.
float child_down_angle(const stem_level_params& lp, const stem& parent, float offset, float base_length, rng& random) {
    if (lp.down_angle_variation_deg >= 0.0f) return random.vary(lp.down_angle_deg, lp.down_angle_variation_deg);
    const float ratio = (parent.length - offset) / std::max(parent.length - base_length, 1e-4f);
    return lp.down_angle_deg +
           lp.down_angle_variation_deg * (1.0f - 2.0f * shape_ratio(crown_shape::conical, ratio));
}

void add_children(const tree_params& params, std::uint64_t seed, tree_skeleton& tree, std::size_t parent_index) {
    const stem parent = tree.stems[parent_index];  // copy: push_back below may reallocate
    const int level = parent.level + 1;
    const stem_level_params& lp = params.level[std::size_t(level)];
    rng random(hash_combine(parent.seed, 1));
    const int count = child_count(params, tree, parent);
    const float base_length = parent.parent < 0 ? params.base_size * parent.length : 0.0f;
    float azimuth = random.uniform(0.0f, 2.0f * k_pi);
    for (int i = 0; i < count; ++i) {
        // Evenly spaced along the free part of the parent, jittered within each slot.
        const float slot = (static_cast<float>(i) + random.uniform(0.2f, 0.8f)) / static_cast<float>(count);
        const float offset = base_length + (parent.length - base_length) * slot;
        const float max_ratio = random.vary(lp.length, lp.length_variation);
        const float length = child_length(params, parent, offset, max_ratio);
        const float down = child_down_angle(lp, parent, offset, base_length, random) * k_deg;
        azimuth += random.vary(params.phyllotaxis_deg, lp.rotate_variation_deg) * k_deg;
        if (length <= 1e-3f) continue;

        const stem_node at = sample_stem(parent, offset / parent.length);
        const glm::vec3 binormal = glm::cross(at.tangent, at.normal);
        const glm::vec3 radial = at.normal * std::cos(azimuth) + binormal * std::sin(azimuth);
        const glm::vec3 direction = glm::normalize(at.tangent * std::cos(down) + radial * std::sin(down));
        // W&P radius_child = radius_parent * (length_child / length_parent)^RatioPower.
        float radius = parent.nodes.front().radius * std::pow(length / parent.length, params.ratio_power);
        radius = std::min(radius, k_max_child_radius_fraction * at.radius);

        stem child;
        child.level = level;
        child.parent = static_cast<int>(parent_index);
        child.length = length;
        child.offset_in_parent = offset;
        child.seed = hash_combine(seed, tree.stems.size());
        rng path_random(child.seed);
        child.nodes = trace_path(params, level, {at.position, direction, orthonormal(radial, direction), length, radius},
                                 path_random);
        tree.stems.push_back(std::move(child));
    }
}

void validate(const tree_params& p) {
    if (p.levels < 2 || p.levels > 4)
        throw std::invalid_argument("tree_params: levels must be 2..4, got " + std::to_string(p.levels));
    if (p.ground_stems < 1) throw std::invalid_argument("tree_params: ground_stems must be >= 1");
    if (!(p.height_m > 0.0f)) throw std::invalid_argument("tree_params: height_m must be > 0");
    for (int i = 0; i < p.levels; ++i) {
        const stem_level_params& lp = p.level[std::size_t(i)];
        if (lp.segments < 1 || lp.sides < 3)
            throw std::invalid_argument("tree_params: level " + std::to_string(i) + " needs segments >= 1 and sides >= 3");
    }
}

}  // namespace

float shape_ratio(crown_shape shape, float ratio) {
    const float r = std::clamp(ratio, 0.0f, 1.0f);
    switch (shape) {
    case crown_shape::conical: return 0.2f + 0.8f * r;
    case crown_shape::spherical: return 0.2f + 0.8f * std::sin(k_pi * r);
    case crown_shape::hemispherical: return 0.2f + 0.8f * std::sin(0.5f * k_pi * r);
    case crown_shape::cylindrical: return 1.0f;
    case crown_shape::tapered_cylindrical: return 0.5f + 0.5f * r;
    case crown_shape::flame: return r <= 0.7f ? r / 0.7f : (1.0f - r) / 0.3f;
    case crown_shape::inverse_conical: return 1.0f - 0.8f * r;
    case crown_shape::tend_flame: return r <= 0.7f ? 0.5f + 0.5f * r / 0.7f : 0.5f + 0.5f * (1.0f - r) / 0.3f;
    }
    return 1.0f;
}

stem_node sample_stem(const stem& s, float t) {
    const auto segments = static_cast<float>(s.nodes.size() - 1);
    const float f = std::clamp(t, 0.0f, 1.0f) * segments;
    const auto i = std::min(static_cast<std::size_t>(f), s.nodes.size() - 2);
    const float a = f - static_cast<float>(i);
    const stem_node& n0 = s.nodes[i];
    const stem_node& n1 = s.nodes[i + 1];
    stem_node n;
    n.position = n0.position + (n1.position - n0.position) * a;
    n.tangent = glm::normalize(n0.tangent + (n1.tangent - n0.tangent) * a);
    n.normal = orthonormal(n0.normal + (n1.normal - n0.normal) * a, n.tangent);
    n.radius = n0.radius + (n1.radius - n0.radius) * a;
    return n;
}

tree_skeleton build_tree_skeleton(const tree_params& params, std::uint64_t seed) {
    validate(params);
    tree_skeleton tree;
    rng random(hash_combine(seed, 0));
    const stem_level_params& trunk_level = params.level[0];
    for (int g = 0; g < params.ground_stems; ++g) {
        stem trunk;
        // W&P length_trunk = (Length0 ± Length0V) * Scale; radius_trunk = length_trunk * Ratio.
        trunk.length = params.height_m * random.vary(trunk_level.length, trunk_level.length_variation);
        trunk.seed = g == 0 ? hash_combine(seed, 0) : hash_combine(seed, 0, g);
        const float azimuth = random.uniform(0.0f, 2.0f * k_pi);
        const glm::vec3 outward{std::cos(azimuth), 0.0f, std::sin(azimuth)};
        glm::vec3 base(0.0f);
        glm::vec3 direction = k_up;
        glm::vec3 normal = outward;
        if (params.ground_stems > 1) {
            // Ground stems spread round the clump at the golden angle, leaning outwards.
            const float around = azimuth + float(g) * params.phyllotaxis_deg * k_deg;
            const glm::vec3 out{std::cos(around), 0.0f, std::sin(around)};
            const float lean = random.vary(params.ground_stem_lean_deg, params.ground_stem_lean_deg / 3.0f) * k_deg;
            base = out * (params.ground_stem_spread_m * std::sqrt(random.uniform()));
            direction = glm::normalize(k_up * std::cos(lean) + out * std::sin(lean));
            normal = orthonormal(out, direction);
        }
        trunk.nodes = trace_path(params, 0, {base, direction, normal, trunk.length, trunk.length * params.trunk_radius_ratio},
                                 random);
        tree.stems.push_back(std::move(trunk));
    }
    for (std::size_t i = 0; i < tree.stems.size(); ++i)
        if (tree.stems[i].level + 1 < params.levels) add_children(params, seed, tree, i);
    return tree;
}

}  // namespace sylva
