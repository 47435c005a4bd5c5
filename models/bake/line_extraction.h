#pragma once
// Long thin elements and the lines that stand for them (Deussen 2002 §4.2), for the point and
// line bake (models/bake/point_line_bake.h): which triangles form one element (a needle card, a grass
// blade, a stem's tube), the element's spine, and its lines. Written by hand: meshoptimizer
// simplifies meshes, not polylines, and no library we use fits a centre line to a tube.
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "models/mesh.h"
#include "models/bake/point_sampling.h"

namespace sylva {

// Connected elements: triangles that share a vertex position (so also a vertex index) and the
// same `group` (callers put material, kind and branch in it, so a leaf touching a stem stays
// separate). Returns an element id per entry of `triangles`, numbered 0, 1, ... in the order
// the elements first appear. Written by hand: a union-find over a sorted corner list.
std::vector<std::uint32_t> connected_elements(const mesh_data& mesh,
                                              std::span<const std::uint32_t> triangles,
                                              std::span<const std::uint64_t> group);

// An element's centre line: its vertices sliced across their principal axis into stations
// (a tube's rings, a strip's cross-sections, a card's base and tip), the stations' centroids
// joined base to tip and simplified (Douglas-Peucker) while every removed station stays within
// half the element's width of the line.
struct element_spine {
    std::vector<glm::vec3> points;  // >= 2 unless the element is degenerate (then empty)
    float length = 0.0f;            // of the simplified polyline
    // Twice the mean distance of the element's vertices from the unsimplified centre line: a
    // card's width, a tube's diameter.
    float width = 0.0f;
    float thickness = 0.0f;  // twice the largest such distance: a tapering tube's base diameter
    float error = 0.0f;      // largest distance of a vertex from the simplified polyline
};
element_spine extract_spine(const mesh_data& mesh, std::span<const std::uint32_t> triangles);

// Length over width; 0 for a degenerate element.
float elongation(const element_spine& spine);

// The lines of one element (Deussen 2002 §4.2): one per spine segment, two vertices each. Both
// vertices carry the element's surface normal made perpendicular to the line (or, for a tube
// whose normals cancel, the direction across the line nearest to +y) and the uv of the opaque
// cell centre nearest the segment's midpoint, where the line's colour is read.
// Where the mesh carries Luft 2007's realigned normals scaled by k_a, each line vertex takes the
// normal of the element's vertex nearest to it instead, length included.
struct element_lines {
    std::vector<vertex> vertices;
    float length = 0.0f;  // l contribution
    float error = 0.0f;   // ε_l contribution
};
element_lines build_element_lines(const mesh_data& mesh, std::span<const std::uint32_t> triangles,
                                  std::span<const triangle_coverage> coverage);

}  // namespace sylva
