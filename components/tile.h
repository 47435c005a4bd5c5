#pragma once
// Deussen 2002 §6.2 eco tile: a square of the landscape subdivided until it holds at most N
// plants. Tiles are entities; children are addressed by handle so the hierarchy stays plain data.
// Writer: population spawning (lod/eco_tiles.h, create_tile_entities); read by cull.
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>

#include "ecs/entity.h"

namespace sylva {

struct tile {
    glm::dvec2 min{0.0};  // world x, z of the square's corner, metres
    double size = 0.0;    // side length, metres
    float min_height = 0.0f;  // world y range of the terrain under the square
    float max_height = 0.0f;
    // The plants' bounding spheres stay within reach_m of the square (sideways) and of the
    // terrain range (up and down): the tile's culling box is the square and the height range
    // grown by reach_m. max_scale bounds the plants' scale (draw distances scale with it).
    float reach_m = 0.0f;
    float max_scale = 1.0f;
    ecs::entity parent{};
    std::array<ecs::entity, 4> children{};  // null handles for a leaf tile
    // Every tile's plants (its whole subtree's for an inner tile) are one contiguous range of
    // plant dense indices: the spawner creates plants in eco_tile_tree::order.
    std::uint32_t first_plant = 0;
    std::uint32_t plant_count = 0;
    std::uint16_t depth = 0;

    bool is_leaf() const { return children[0].is_null(); }
};

}  // namespace sylva
