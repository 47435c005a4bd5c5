#pragma once
// A plant's point and line representation (Deussen, Colditz, Stamminger, Drettakis 2002, §4):
// its full mesh split into parts, each part's triangles in a random order, a point list for the
// compact parts and a line list for the long thin ones. At run time a part is drawn as a prefix
// of its triangle list plus a prefix of its point or line list (§5.3), so its level of detail is
// a few counts (components/point_prefix.h) and drawing it needs no per-frame geometry work.
//
// Parts are grouped by cells: a small plant is one cell; a big one is split by a shallow octree
// (§6.1) so each cell chooses its own level of detail. A cell's parts are at most
// k_max_cell_parts; each is one primitive kind and one material.
//
// Point order. The paper stores a part's 2n points "in the same order" as its n triangles, so
// for the §5.3 blend (first t triangles plus the points of the remaining triangles) the points
// drawn are a range in the middle of the list. We store the points in the REVERSE of the
// triangle order instead (the points of triangle n-1 first, of triangle 0 last). Then the
// points of triangles t..n-1 are a prefix of the list, exactly like the "first p points" of the
// points-only regime, and every draw in the system is a prefix. A prefix of a randomly ordered
// list is a random subset whichever end it starts from, so nothing of the paper's sampling
// argument changes.
//
//   triangles (random order)   T0  T1  T2 ... T(t-1) | Tt ... T(n-1)
//   points    (reverse order)  P(n-1),P(n-1) ... P(t),P(t) | P(t-1) ... P0,P0
//                              \___ points_after[t] ___/
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "models/mesh.h"

namespace sylva {

// Bump whenever the bake changes what it produces (the bake cache keys on it).
constexpr std::uint32_t k_point_line_format = 2;  // 2: lines keep Luft 2007's normals
// Parts per cell: enough for bark, twigs, foliage and one important kind (petals).
constexpr std::size_t k_max_cell_parts = 4;

enum class lod_primitive : std::uint8_t {
    points,  // §4.1: compact parts (leaves, petals, fronds, trunk and thick branches)
    lines,   // §4.2: long thin parts (needles, grass blades, twigs)
};

struct lod_part {
    lod_primitive primitive = lod_primitive::points;
    material_kind material = material_kind::leaf;  // which texture colours its points or lines
    part_kind kind = part_kind::leaf;              // the part kind most of its area has
    // §4.3 importance: 1 for ordinary parts; above 1 the part keeps more primitives (it is
    // reduced more slowly). Set by the species or computed from colour distinctiveness.
    float importance = 1.0f;
    // World area of the part's triangles at scale 1 (one side; alpha-tested texels that are
    // cut away do not count): A_p for a point part, A_l for a line part (§5, Eq. 1 and 2).
    float area_m2 = 0.0f;
    glm::vec3 center{0.0f};  // area-weighted centroid, model space at scale 1: r is measured to it
    // Triangles: indices [first_index, first_index + 3 * triangle_count) of
    // point_line_model::triangles, in random order.
    std::uint32_t first_index = 0;
    std::uint32_t triangle_count = 0;
    // Points (primitive == points): vertices [first_point, first_point + point_count) of
    // point_line_model::points, in reverse triangle order (see the header comment);
    // points_after[first_after + t] (t = 0..triangle_count) is how many of them belong to
    // triangles t..n-1, so points_after[first_after] == point_count and
    // points_after[first_after + triangle_count] == 0.
    std::uint32_t first_point = 0;
    std::uint32_t point_count = 0;
    std::uint32_t first_after = 0;
    // True when every triangle has exactly two points (similar areas, §4.1 stratified
    // sampling); false when the 2n points were spread by area.
    bool stratified = false;
    // Lines (primitive == lines): vertices [2 * first_line, 2 * (first_line + line_count)) of
    // point_line_model::lines, in random order, each line two vertices.
    std::uint32_t first_line = 0;
    std::uint32_t line_count = 0;
    float line_length_m = 0.0f;  // l: total length of the part's lines, scale 1
    float line_error_m = 0.0f;   // ε_l: largest distance of the part's geometry from its lines
};

struct lod_cell {
    glm::vec3 bounds_min{0.0f};  // model space at scale 1
    glm::vec3 bounds_max{0.0f};
    std::uint32_t first_part = 0;
    std::uint32_t part_count = 0;  // <= k_max_cell_parts
};

struct point_line_model {
    // The full mesh's vertices with its triangles regrouped: each part's triangles contiguous
    // and shuffled; `submeshes` holds one entry per part (same order as `parts`), `parts` the
    // triangle records in the new order.
    mesh_data triangles;
    // One vertex per point: where it was sampled, its triangle's normal, and the texture
    // coordinate there (the colour a point takes).
    std::vector<vertex> points;
    // Two vertices per line; the normal is the element's surface normal (or the stem's side
    // direction for twigs), the uv where the line's colour is read.
    std::vector<vertex> lines;
    std::vector<std::uint32_t> points_after;
    std::vector<lod_part> parts;
    std::vector<lod_cell> cells;  // one for plants that are not split
};

}  // namespace sylva
