#pragma once
// Deussen 2002 §6.2 eco tile: a square of the landscape subdivided until it holds at most N
// plants. Tiles are entities; children are addressed by handle so the hierarchy stays plain data.
// Writer: population spawning (tile build); read by hierarchical culling.
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>

#include "ecs/entity.h"

namespace sylva {

struct tile {
    glm::dvec2 min{0.0};  // x, z of the square's corner, metres
    double size = 0.0;    // side length, metres
    float min_height = 0.0f;
    float max_height = 0.0f;
    ecs::entity parent{};
    std::array<ecs::entity, 4> children{};  // null handles for a leaf tile
    std::uint32_t first_plant = 0;          // plants of a leaf tile are a contiguous range
    std::uint32_t plant_count = 0;
    std::uint16_t depth = 0;
};

}  // namespace sylva
