#include "models/generate/flower_generator.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "models/generate/plant_mesh_builder.h"
#include "models/generate/plant_textures.h"
#include "models/random.h"

namespace sylva {
namespace {

constexpr float k_pi = 3.14159265358979f;
constexpr float k_deg = k_pi / 180.0f;
constexpr glm::vec3 k_up{0.0f, 1.0f, 0.0f};
constexpr triangle_part k_stem_part{0, 0, part_kind::bark, 0};
constexpr triangle_part k_leaf_part{0, 1, part_kind::leaf, 0};
constexpr triangle_part k_petal_part{0, 1, part_kind::petal, 0};

struct flower_detail {
    int stem_sides, stem_segments;
    int leaves, leaf_segments;
    int petals, petal_segments;
};

flower_detail detail_for(tree_detail detail) {
    switch (detail) {
        case tree_detail::full: return {8, 12, 5, 4, 12, 4};
        case tree_detail::reduced: return {3, 2, 2, 1, 6, 1};
        case tree_detail::far: return {3, 1, 1, 1, 4, 1};
    }
    return {8, 12, 5, 4, 12, 4};
}

// The stem: a gentle arc leaning to one side, thinning towards the blossom.
std::vector<tube_ring> stem_rings(float height, glm::vec3 lean_dir, float lean, int segments) {
    std::vector<tube_ring> rings;
    glm::vec3 p{0.0f};
    const float step = height / float(segments);
    const glm::vec3 normal = glm::normalize(glm::cross(lean_dir, k_up));
    for (int k = 0; k <= segments; ++k) {
        const float t = float(k) / float(segments);
        const float angle = lean * t;
        const glm::vec3 tangent = k_up * std::cos(angle) + lean_dir * std::sin(angle);
        rings.push_back({p, tangent, normal, 0.0045f * (1.0f - 0.4f * t)});
        p += tangent * step;
    }
    return rings;
}

// A leaf or petal: a strip from `base` outwards along `radial` (unit, horizontal-ish), rising
// at `rise_start` and curving by `curl` over its length, front facing up.
void add_curved_card(plant_mesh_builder& out, glm::vec3 base, glm::vec3 radial, glm::vec3 up, float length,
                     float width, float rise_start, float curl, int segments, const uv_rect& region,
                     const triangle_part& part) {
    const glm::vec3 across = glm::normalize(glm::cross(radial, up));
    std::vector<glm::vec3> spine{base};
    std::vector<float> widths(std::size_t(segments) + 1, 0.5f * width);
    std::vector<glm::vec3> sides(std::size_t(segments) + 1, across);
    for (int k = 1; k <= segments; ++k) {
        const float angle = rise_start + curl * (float(k) - 0.5f) / float(segments);
        spine.push_back(spine.back() + (radial * std::cos(angle) + up * std::sin(angle)) * (length / float(segments)));
    }
    add_strip(out, spine, widths, sides, region, part);
    const glm::vec3 along = glm::normalize(spine.back() - spine.front());
    out.leaves.push_back({(spine.front() + spine.back()) * 0.5f, glm::normalize(glm::cross(across, along)),
                          std::max(length, width), part.parent_branch, part.kind});
}

}  // namespace

mesh_data generate_flower(std::uint64_t seed, tree_detail detail) {
    const flower_detail d = detail_for(detail);
    rng random(hash_combine(seed, 0));
    const float height = random.uniform(0.45f, 0.75f);
    const float azimuth = random.uniform(0.0f, 2.0f * k_pi);
    const glm::vec3 lean_dir{std::cos(azimuth), 0.0f, std::sin(azimuth)};
    const float lean = random.uniform(5.0f, 20.0f) * k_deg;

    plant_mesh_builder bark;
    const std::vector<tube_ring> rings = stem_rings(height, lean_dir, lean, 12);
    std::vector<tube_ring> coarse;
    for (int k = 0; k <= d.stem_segments; ++k) coarse.push_back(rings[std::size_t(k * 12 / d.stem_segments)]);
    add_tube(bark, coarse, d.stem_sides, 0.03f, k_stem_part);

    plant_mesh_builder foliage;
    // Leaves alternate up the lower half of the stem; fewer at coarser detail, each enlarged so
    // the total leaf area is that of the full set (5 leaves).
    const float leaf_scale = std::sqrt(5.0f / float(d.leaves));
    rng leaf_random(hash_combine(seed, 1));
    for (int i = 0; i < d.leaves; ++i) {
        const float t = 0.08f + 0.4f * (float(i) + 0.5f) / float(d.leaves);
        const tube_ring& at = rings[std::size_t(std::lround(t * 12.0f))];
        const float around = azimuth + float(i) * 137.5f * k_deg + leaf_random.uniform(-0.3f, 0.3f);
        const glm::vec3 radial{std::cos(around), 0.0f, std::sin(around)};
        const float length = leaf_random.uniform(0.09f, 0.13f) * leaf_scale;
        add_curved_card(foliage, at.position + radial * at.radius, radial, k_up, length, 0.35f * length,
                        leaf_random.uniform(35.0f, 55.0f) * k_deg, -60.0f * k_deg, d.leaf_segments,
                        k_flower_leaf_region, k_leaf_part);
    }
    // The blossom, facing along the stem's tip: a cup of petals opening outwards round a disc.
    const tube_ring& top = rings.back();
    const glm::vec3 head_up = top.tangent;
    const glm::vec3 head_x = top.normal;
    const glm::vec3 head_z = glm::cross(head_up, head_x);
    const float petal_length = random.uniform(0.03f, 0.042f);
    // Fewer petals keep their length (the blossom's outline) and widen to the same total area.
    const float petal_width = 0.7f * petal_length * 12.0f / float(d.petals);
    for (int i = 0; i < d.petals; ++i) {
        const float around = 2.0f * k_pi * (float(i) + 0.5f * float(i % 2)) / float(d.petals);
        const glm::vec3 radial = head_x * std::cos(around) + head_z * std::sin(around);
        add_curved_card(foliage, top.position + radial * 0.006f + head_up * 0.004f, radial, head_up,
                        petal_length, petal_width, 45.0f * k_deg, -40.0f * k_deg, d.petal_segments,
                        k_flower_petal_region, k_petal_part);
    }
    const float disc = 0.022f;
    const card centre{top.position + head_up * 0.008f - head_z * (0.5f * disc), head_z, head_x, disc, disc};
    add_card(foliage, centre, k_flower_centre_region, k_petal_part);
    foliage.leaves.push_back(card_record(centre, 0, part_kind::petal));
    return assemble_plant_mesh(std::move(bark), std::move(foliage));
}

}  // namespace sylva
