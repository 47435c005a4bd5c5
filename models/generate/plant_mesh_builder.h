#pragma once
// Building blocks shared by the plant generators (trees, grass, flowers, ferns): a mesh under
// construction that records, with every triangle, which part of the plant it belongs to, and
// the two shapes every plant is made of — tubes along a stem and textured cards.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "models/mesh.h"

namespace sylva {

// A rectangle of the texture: a card's uvs span it (atlases hold several looks in one texture).
struct uv_rect {
    glm::vec2 min{0.0f};
    glm::vec2 max{1.0f};
};

struct plant_mesh_builder {
    std::vector<vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<triangle_part> parts;  // one per triangle in indices
    std::vector<leaf_record> leaves;

    void add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, const triangle_part& part) {
        indices.insert(indices.end(), {a, b, c});
        parts.push_back(part);
    }
};

// One point of a tube's centre line with its frame (tangent and normal unit, perpendicular).
struct tube_ring {
    glm::vec3 position;
    glm::vec3 tangent;
    glm::vec3 normal;
    float radius;
};

// A generalized cylinder through the rings: sides + 1 vertices per ring (the seam repeats with
// u = 1), radial normals, v along the tube in units of `v_scale` metres. Counter-clockwise
// seen from outside.
void add_tube(plant_mesh_builder& out, std::span<const tube_ring> rings, int sides, float v_scale,
              const triangle_part& part);

// A flat card: `base` is the middle of its bottom edge, `axis` (unit) runs base to tip, `side`
// (unit) across. The front (counter-clockwise) faces cross(side, axis). uv: u across from
// region.min.x, v = region.max.y at the base and region.min.y at the tip (tip on the top row).
struct card {
    glm::vec3 base;
    glm::vec3 axis;
    glm::vec3 side;
    float length;
    float width;
};
void add_card(plant_mesh_builder& out, const card& c, const uv_rect& region, const triangle_part& part);

// A card bent along its length: `spine` points (base first) with the card's half-width at each,
// `across` the unit side direction per point. Each span is one quad; normals follow the bend.
void add_strip(plant_mesh_builder& out, std::span<const glm::vec3> spine, std::span<const float> half_width,
               std::span<const glm::vec3> across, const uv_rect& region, const triangle_part& part);

// The record of a foliage element that was just added as a card.
leaf_record card_record(const card& c, std::uint32_t parent_branch, part_kind kind);

// Bark first, then foliage, as one mesh with a sub-mesh per non-empty material (a plant without
// bark, such as grass, has only the leaf sub-mesh); parts, leaves and bounds filled in.
mesh_data assemble_plant_mesh(plant_mesh_builder&& bark, plant_mesh_builder&& foliage);

}  // namespace sylva
