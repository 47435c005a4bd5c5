#pragma once
// Deussen 2002 §6.2: "For each eco file a rough point representation for the geometry of the
// entire tile is computed by randomly collecting points from the geometry approximations of
// the plant instances ... the rough point approximations of the children are merged to form a
// point approximation of the overall content." Far tiles draw that set instead of their plants,
// so a distant hillside costs a few prefixes instead of thousands of plants.
//
// Built once when a scene with the point/line representation is spawned: per eco tile, one set
// per (species, material, points or lines), in world space relative to the tile's origin and
// shuffled, so every prefix is a random subset of the tile's plants' samples. A leaf tile takes
// from each plant a prefix of its own randomly ordered list, in proportion to the plant's area
// (one density per set: as high as k_tile_samples and the sparsest plant's list allow); an
// inner tile takes prefixes of its children's sets the same way. "Rough": far tiles need few.
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "ecs/world.h"
#include "models/bake/point_line_model.h"
#include "resources/scene_assets.h"

namespace sylva {

inline constexpr std::uint32_t k_tile_samples = 1024;
// Items of tile sets carry this bit in draw_item::instance, with the set's index below it.
inline constexpr std::uint32_t k_tile_item_bit = 0x80000000u;

// One aggregated set of a tile.
struct tile_point_part {
    std::uint32_t tile = 0;  // dense index in the tile table (= eco tile node index)
    std::uint16_t mesh = 0;  // points or lines relative to the tile's origin
    std::uint16_t mesh_splats = 0;  // line sets: the lines' end points as splats (short lines)
    lod_primitive primitive = lod_primitive::points;
    float texture_layer = 0.0f;
    float area_m2 = 0.0f;  // A of Eq. 1 / Eq. 2: the plants' parts, scaled (a far tile needs coverage,
                           // not importance: no part of it is polygonal)
    float line_length_m = 0.0f;  // l: the total length of all the tile's plants' lines
    float line_error_m = 0.0f;   // ε_l: the largest of the plants'
    std::uint32_t count = 0;     // samples in the mesh
    std::uint32_t stands_for = 0;  // samples of all the tile's plants it is drawn from (n_l of Eq. 2)
};

// The tile sets as a world resource (read by aggregate_eco_tiles and build_draw_list).
struct tile_point_sets {
    std::vector<tile_point_part> parts;
    std::vector<std::uint32_t> first_part;  // per tile, parts [first_part[t], first_part[t + 1])
    std::vector<glm::dvec3> origin;         // per tile, world: the centre of its plants' box
    std::vector<float> radius;              // per tile: sphere around its plants' spheres, from origin
                                            // (the centre of their box; a plantless tile: its square)
};

// Builds every tile's sets from the spawned plants and tiles, adding their meshes to `assets`
// (before the renderer is made). Empty when the world has no tiles or no species has parts.
tile_point_sets build_tile_point_sets(const ecs::world& world, scene_assets& assets, std::uint64_t seed);

}  // namespace sylva
