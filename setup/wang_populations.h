#pragma once
// Behrendt 2005 §3.4 in a scenario: the Wang tiling that every population with placement
// "wang_tiles" shares (scenario.wang_tiles; models/terrain/wang_tiles.h), each such population's
// tile set, and its plants as the tiling lays them. The tiling's lattice starts at the terrain's
// corner; a tile set is thrown for the density the population's count asks over its area.
#include <cstdint>
#include <vector>

#include "models/terrain/wang_tiles.h"
#include "resources/scene_assets.h"
#include "scenarios/scenario.h"

namespace sylva {

// The seed of the scenario's tiling: every corner colour is hashed from it.
std::uint64_t wang_tiling_seed(const scenario& s);
// Lattice corner (0, 0): the terrain's (x0, z0) corner.
glm::dvec2 wang_lattice_origin(const scenario& s);
// How far population p's plants reach from their positions: the farthest vertex of its
// species' full mesh from the vertical axis, at the population's largest scale.
float wang_reach_m(const scenario& s, std::size_t p, const scene_assets& assets);
// The tile set of population `p` (which must have placement "wang_tiles"), its edge strips as
// wide as `reach_m`. Throws std::runtime_error naming the population when the scenario's tiles
// are too small for its spacing and reach.
wang_tile_set wang_tile_set_of(const scenario& s, std::size_t p, float reach_m);
// Population p's plants: the tiling's plants inside its area, tile row by tile row.
std::vector<placement> place_wang_population(const scenario& s, std::size_t p, float reach_m);

}  // namespace sylva
