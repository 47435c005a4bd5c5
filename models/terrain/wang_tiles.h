#pragma once
// Wang tiles whose content is the real plants (Behrendt 2005 §3.4, after Cohen et al. 2003 "Wang
// tiles for image and texture generation"): a square tile set whose plant placements match
// across tile borders, and a stochastic tiling of the plane that any thread can evaluate for any
// tile on its own.
//
// Corner colours (Lagae & Dutré 2006, "An alternative for Wang tiles: colored edges versus
// colored corners"): each lattice corner has one of C colours, and a tile is the one whose four
// corners have those colours; with the complete set of C⁴ tiles every colouring is a valid tiling.
// Two tiles that share an edge share its two corners, so edges match (an edge's colour is the
// pair of its corner colours: C² edge colours per direction, 4 with the default C = 2), and
// tiles that share only a corner agree there too, which edge-coloured tiles cannot promise (the
// corner problem of Cohen et al.'s Poisson tiles).
//
// The tiling: each corner's colour is a hash of the tiling seed and the corner's lattice
// coordinates (Lagae & Dutré 2005 "A procedural object distribution function" tile by hashing
// likewise), so a tile's type depends on nothing but (seed, i, j): the same for any thread count
// and any order of evaluation, and not periodic.
//
// Plants that match across borders (Poisson disk, minimum spacing r): a tile is cut into regions
// whose content is fixed by the colours around them.
//  - corner squares of half-side m around each corner, one Poisson set per corner colour;
//  - edge strips of half-width w along each edge between the corner squares, one set per
//    direction and pair of end colours, thrown around the two corner sets it touches;
//  - the interior (at least w from the tile's border), one set per tile, thrown around the
//    tile's share of the corner and strip sets.
// A tile owns the part of each shared set that lies inside it (half-open: [0, T)²). With w = r
// and m = w + r/√2, no two points anywhere in a tiling are closer than r: interior points are r
// from every other tile, strips that meet at a corner are √2·(m − w) = r apart, and every other
// pair was thrown against each other. Every plant's scale, yaw, seed and tint are drawn with its
// set, so a tile type is the same plants wherever it lies (which its shell texture needs).
#include <array>
#include <cstdint>
#include <vector>

#include "models/terrain/placement.h"
#include "models/terrain/wang_tile_rules.h"

namespace sylva {

// A tile's corner colours as an index into the set: sw + C·(se + C·(nw + C·ne)), where sw is at
// the tile's (x0, z0), se at (x1, z0), nw at (x0, z1) and ne at (x1, z1).
constexpr std::uint32_t wang_tile_index(std::uint32_t colours, std::uint32_t sw, std::uint32_t se, std::uint32_t nw,
                                        std::uint32_t ne) {
    return sw + colours * (se + colours * (nw + colours * ne));
}
// The corner colours of tile `index`: {sw, se, nw, ne}.
std::array<std::uint32_t, 4> wang_tile_corners(std::uint32_t colours, std::uint32_t index);

// The colour of lattice corner (i, j) (the corner at x0 + i·T, z0 + j·T) in the tiling `seed`.
std::uint32_t wang_corner_colour(std::uint64_t seed, std::int64_t i, std::int64_t j, std::uint32_t colours);
// The type of tile (i, j): the tile whose sw corner is lattice corner (i, j).
std::uint32_t wang_tile_at(std::uint64_t seed, std::int64_t i, std::int64_t j, std::uint32_t colours);

struct wang_tile_set {
    wang_tile_rules rules;
    // By tile index, each tile's plants in tile coordinates [0, T)² (x, z from the tile's sw
    // corner), in a fixed order: its corner, strip and interior shares.
    std::vector<std::vector<placement>> tiles;
    // By tile index, the plants of the neighbouring tiles that the tile's colours fix and that
    // may reach into it (the rest of its four corner squares and four edge strips), in the same
    // tile coordinates, so outside [0, T)². With rules.reach_m at least any plant's reach, these
    // and `tiles` are every plant that can cover the tile, whatever tiles lie around it.
    std::vector<std::vector<placement>> reaching;
};

// The complete set of C⁴ tiles. Deterministic in (rules, seed); throws std::invalid_argument
// with wang_rules_problem's reason.
wang_tile_set build_wang_tile_set(const wang_tile_rules& rules, std::uint64_t seed);

// The plants of the tiling `tiling_seed` of the tile lattice anchored at `origin` (lattice corner
// (0, 0)) that fall in `area` = {x0, z0, x1, z1} (half-open), tile row by tile row (z, then x),
// each tile's plants in the set's order, in world coordinates.
std::vector<placement> place_wang_tiles(const wang_tile_set& set, std::uint64_t tiling_seed, glm::dvec2 origin,
                                        const std::array<double, 4>& area);

}  // namespace sylva
