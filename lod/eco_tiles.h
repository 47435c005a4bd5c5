#pragma once
// Eco tiles (Deussen 2002 §6.2): "vast plant populations are stored in a set of quadratic tiles
// that fit together ... If a single tile has too many instances, it is further subdivided into
// sub-tiles, until a given number of instances per tile is achieved." build_eco_tiles is the
// pure subdivision (a quadtree over plant positions); create_tile_entities turns its nodes into
// tile entities that cull_system walks hierarchically.
//
// How the spawner uses it (plants of all populations together):
//   std::vector<glm::dvec2> xz = ...;                       // terrain-centred, one per plant
//   const eco_tile_tree tree = build_eco_tiles(xz, area, max_plants_per_tile);
//   for (std::uint32_t slot : tree.order) create plant entity for plant `slot`;
//   world.align<world_transform, bounds, plant_instance, lod_state, ...>();
//   create_tile_entities(world, tree, terrain, {reach_m, max_scale, world_offset});
// Plant dense index i must then be plant tree.order[i] (cull_system checks it cheaply).
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <span>
#include <vector>

#include "ecs/world.h"
#include "models/terrain/terrain.h"

namespace sylva {

// Subdivision stops at this depth even if a tile still holds more than N plants (many plants
// at one spot); 24 levels split a 100 km square into 6 mm tiles.
inline constexpr std::uint16_t k_max_eco_tile_depth = 24;
inline constexpr std::uint32_t k_no_eco_tile = std::numeric_limits<std::uint32_t>::max();

struct eco_tile_node {
    glm::dvec2 min{0.0};  // x, z of the square's corner (same frame as the plant positions)
    double size = 0.0;
    std::uint32_t parent = k_no_eco_tile;
    // Quadrants (-x -z), (+x -z), (-x +z), (+x +z); all k_no_eco_tile for a leaf.
    std::array<std::uint32_t, 4> children{k_no_eco_tile, k_no_eco_tile, k_no_eco_tile,
                                          k_no_eco_tile};
    std::uint16_t depth = 0;
    std::uint32_t first_plant = 0;  // slots [first_plant, first_plant + plant_count) of `order`:
    std::uint32_t plant_count = 0;  // the whole subtree's plants, contiguous at every level

    bool is_leaf() const { return children[0] == k_no_eco_tile; }
};

struct eco_tile_tree {
    // Depth-first preorder from the single root (nodes[0]): parents before children, children
    // in quadrant order, so leaves appear in increasing first_plant order.
    std::vector<eco_tile_node> nodes;
    // order[slot] = the input plant placed at dense slot `slot`. Each leaf's plants are
    // contiguous; within a tile plants keep their input order (stable).
    std::vector<std::uint32_t> order;
};

// The root is the square with corner (area[0], area[1]) and side max(width, depth) of area
// {x0, z0, x1, z1}, grown to hold any plant outside it. A tile holding more than
// max_plants_per_tile plants (>= 1) is split into four equal quadrants (a plant on a split line
// goes to the + side). Deterministic; O(plants * depth).
eco_tile_tree build_eco_tiles(std::span<const glm::dvec2> plant_xz, std::array<double, 4> area,
                              std::uint32_t max_plants_per_tile);

// What the tile boxes must allow for beyond the terrain: the largest plant bounding sphere's
// reach from its base ((center_height + radius) * scale over all species and scales), the
// largest plant scale, and the world offset added to every plant position.
struct eco_tile_extent {
    float reach_m = 0.0f;
    float max_scale = 1.0f;
    glm::dvec3 world_offset{0.0};
};

// One entity per node, in node order, each with components::tile (world min/size, terrain
// height range under the square from the heightfield's grid, extent, parent and children
// handles, plant range, depth) and a tile_visibility. Returns the handles (index = node index).
std::vector<ecs::entity> create_tile_entities(ecs::world& world, const eco_tile_tree& tree,
                                              const heightfield& terrain,
                                              const eco_tile_extent& extent);

}  // namespace sylva
