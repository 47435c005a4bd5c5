#pragma once
// The leaves LoDF collapses (models/bake/lodf_bake.h): the foliage of a mesh split into units,
// grouped into clusters, and the triangles of every leaf F^r holds, originals and those the
// collapses make from four of their vertices (Rebollo 2006 Eq. 3: no new vertices).
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "models/bake/lodf_structure.h"
#include "models/mesh.h"

namespace sylva {

// One connected piece of foliage triangles.
struct foliage_leaf {
    std::vector<std::uint32_t> triangles;  // into mesh_data::indices / 3, ascending
    float area = 0.0f;
    glm::vec3 centre{0.0f};                // area-weighted
    glm::vec3 normal{0.0f, 1.0f, 0.0f};    // area-weighted, unit
    // The vertices at the leaf texture's corners (extremes of u + v and u − v): bottom-left,
    // bottom-right, top-right, top-left. A made leaf is a quad on four such corners.
    std::array<std::uint32_t, 4> corners{};
    std::uint32_t branch = 0;              // the stem carrying it (triangle_part::branch), else 0
};

// `mesh` without its foliage: every submesh but the material-leaf ones (indices copied, submeshes
// rebased), the vertices too when `keep_vertices`, else none (an index list over the same
// vertices, mesh_pool::add_indices); bounds kept, per-triangle parts and leaf records dropped.
mesh_data non_foliage_part(const mesh_data& mesh, bool keep_vertices = true);

// The connected pieces (by shared vertex index) of the triangles of every material-leaf submesh,
// in the order of their first triangle.
std::vector<foliage_leaf> find_foliage_leaves(const mesh_data& mesh);

// `groups` clusters of consecutive leaves along the branch hierarchy (depth first over
// triangle_part's stems) when `has_hierarchy`, else along a Morton curve through the centres;
// sizes differ by at most one. Each cluster lists its leaves in that order.
std::vector<std::vector<std::uint32_t>> cluster_foliage_leaves(const mesh_data& mesh,
                                                               const std::vector<foliage_leaf>& leaves,
                                                               bool has_hierarchy, std::uint32_t groups);

// The quad a collapse makes of leaves with corners `a` and `b` (Rebollo 2006 Eq. 3: on their
// vertices): each of the four texture corners taken from one leaf or the other, so the texture
// spans the new leaf once; of the sixteen such quads, the one whose area is nearest
// `target_area` (the pair's), a folded one only when all are.
std::array<std::uint32_t, 4> collapse_quad(const std::vector<vertex>& vertices, const std::array<std::uint32_t, 4>& a,
                                           const std::array<std::uint32_t, 4>& b, float target_area);

// Widens a made leaf's quad `q` towards `target_area`: each corner may move to the same texture
// corner of any original leaf under it (`candidates[c]`). First the rectangle of that area about
// `centre` in the plane of `normal`, along the candidates' widest spread, each corner snapped to
// the nearest candidate of its kind (all eight ways the texture can lie on it); then one corner
// at a time while that brings the area nearer. A made leaf of two leaves has only their corners;
// one higher up reaches across its whole subtree, so it shrinks less with every level. On
// broadleaf the made leaves keep 71 % of their originals' area at the first level, 59 % at the
// second, 47 % at the fourth and 41 % at the sixth (on 16 quads of the children's corners alone:
// 57 %, 38 % and 28 %). Eq. 3 itself is the limit: over all 256 quads on the corners of a
// second-level leaf's four originals the best keeps 59 % and the largest 67 %, as overlapping
// cards span less than the sum of their areas.
std::array<std::uint32_t, 4> widen_quad(const std::vector<vertex>& vertices, std::array<std::uint32_t, 4> q,
                                        const std::array<std::vector<std::uint32_t>, 4>& candidates, float target_area,
                                        const glm::vec3& centre, const glm::vec3& normal);

// The area of the quad q0 q1 q2 q3, as two triangles q0 q1 q2 and q0 q2 q3.
float quad_area(const std::vector<vertex>& vertices, const std::array<std::uint32_t, 4>& q);

// Fills the structure's node index ranges and appends every leaf's triangles to `indices`,
// cluster by cluster in array order: an original's own, a made leaf's quad on `made_corners`
// (by collapse). Returns the made quads' mean area over that of the originals under them.
float append_lodf_indices(const mesh_data& mesh, const std::vector<foliage_leaf>& leaves,
                          const std::vector<std::array<std::uint32_t, 4>>& made_corners, lodf_structure& structure,
                          std::vector<std::uint32_t>& indices);

}  // namespace sylva
