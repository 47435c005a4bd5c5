#pragma once
// Per-triangle measurements and sampling for the point and line bake (models/bake/point_line_bake.h):
// how much of a triangle survives the alpha test, its mean texture colour, and random points on
// its opaque part (Deussen 2002 §4.1).
//
// Coverage is measured on a fixed pattern: each edge cut into k_coverage_subdivision pieces
// gives k_coverage_cells equal sub-triangles ("cells"), and a cell counts as opaque when the
// texture passes the alpha test at its centre. Equal cells make the opaque area a plain count.
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "models/image/image.h"
#include "models/mesh.h"
#include "models/random.h"

namespace sylva {

// The texture a material samples and whether it is alpha-tested, as the renderer and
// models/bake/billboard_bake.h treat them: leaf and billboard sample the leaf texture and discard
// below alpha 0.5; bark and ground sample the bark texture and are opaque. A null or empty
// texture is untextured: opaque, mid grey.
struct surface_texture {
    const image_rgba8* texture = nullptr;
    bool alpha_tested = false;
};
surface_texture surface_of(material_kind material, const image_rgba8& leaf_texture,
                           const image_rgba8& bark_texture);

// Bilinear, wrapping like GL_REPEAT, texel row 0 at v = 0 (as models/bake/billboard_bake.cpp
// samples). Alpha in [0, 1]; colour linear rgb in [0, 1] (the generated textures store linear
// albedo), weighted by alpha on an alpha-tested surface so cut-away texels add no colour.
float texture_alpha(const image_rgba8& texture, glm::vec2 uv);
glm::vec3 texture_colour(const image_rgba8& texture, glm::vec2 uv, bool alpha_weighted);
// What the renderer's alpha test keeps (alpha >= 0.5); always true on an opaque surface.
bool passes_alpha_test(const surface_texture& surface, glm::vec2 uv);

constexpr int k_coverage_subdivision = 8;
constexpr int k_coverage_cells =
    k_coverage_subdivision * k_coverage_subdivision;  // 64: one bit each
static_assert(k_coverage_cells <= 64);

// Barycentric coordinates (b1, b2) are the weights of corners 1 and 2; corner 0 has 1 - b1 - b2.
struct triangle_corners {
    std::array<vertex, 3> v;
};
// The centre of cell `cell` (0 .. k_coverage_cells - 1) in barycentric coordinates.
glm::vec2 coverage_cell_centre(int cell);
// Position, normal and uv at a barycentric point. The normal is the interpolated vertex normal
// (what the renderer shades the triangle with there), or the geometric normal where that
// interpolation vanishes.
vertex point_at(const triangle_corners& corners, glm::vec2 barycentric);
float triangle_area(const triangle_corners& corners);

struct triangle_coverage {
    float area = 0.0f;                // geometric, m²
    float opaque_area = 0.0f;         // area * opaque cells / k_coverage_cells
    std::uint64_t opaque_cells = 0;   // bit c: cell c's centre passes the alpha test
    glm::vec3 colour{0.0f};           // mean texture colour over the opaque cells' centres
    glm::vec3 opaque_centroid{0.0f};  // mean position of the opaque cells' centres
};
triangle_coverage measure_coverage(const triangle_corners& corners, const surface_texture& surface);

// A sub-triangle of a triangle, corners in barycentric coordinates.
struct barycentric_region {
    std::array<glm::vec2, 3> corner{glm::vec2{0.0f, 0.0f}, glm::vec2{1.0f, 0.0f},
                                    glm::vec2{0.0f, 1.0f}};
};
// The two halves of equal area either side of the median from the corner opposite the longest
// edge: the strata of the two-points-per-triangle sampling (Deussen 2002 §4.1).
std::array<barycentric_region, 2> triangle_halves(const triangle_corners& corners);

// A uniformly distributed point of `region` that passes the alpha test: up to k tries by
// rejection (uniform over the region's opaque part), then the centre of a random opaque cell in
// the region (else of any opaque cell), which the coverage found opaque. With no opaque cell at
// all, the last try.
vertex sample_opaque_point(const triangle_corners& corners, const triangle_coverage& coverage,
                           const surface_texture& surface, const barycentric_region& region,
                           rng& random);

// Deussen 2002 §4.1: two points per triangle (stratified) when "all triangles of the object
// have about the same area": the largest over the smallest area, after dropping the 5 % tails
// at either end so a few slivers do not decide, is below `ratio`. `areas` must not be empty.
bool similar_areas(std::span<const float> areas, float ratio);

// Deussen 2002 §4.1: 2n points for n triangles "in a way that equal surfaces receive equal
// numbers of points", small triangles perhaps none. Systematic sampling over the cumulative
// area: triangle i gets floor or ceil of its share 2n a_i / A, a random offset deciding which,
// so the counts are proportional to area with the least variance. Returns a count per area.
std::vector<std::uint32_t> area_weighted_counts(std::span<const float> areas, rng& random);

}  // namespace sylva
