#pragma once
// Behrendt 2005 §3.2: the triangles of a shell slice are slanted toward the viewer so that a
// grazing view still crosses them. For a slice triangle x_1, x_2, x_3 with centre
// m = (x_1 + x_2 + x_3) / 3, viewer c and v = c − m, the triangle faces the viewer when
//   v · (m − x_i) = 0                                          (Eq. 1)
// and a vertical shift x'_i = x_i + (0, d_i, 0) solves it with
//   d_i = v · (m − x_i) / v_y                                   (Eq. 2)
// which grows without bound as the view grazes (v_y → 0); the paper limits it to
//   d_i = f · v · (m − x_i) / ‖v‖                               (Eq. 2, limited)
// so |d_i| <= f·‖m − x_i‖: the shift is proportional to the cosine between the view and the
// vertex's offset from the centre, and f sets the largest slant, ϕ_max = atan(f · cos) (the paper
// uses f = 1). The shell vertex shader (shaders/shell.vert) computes the same; these are its
// reference for tests.
#include <glm/vec3.hpp>
#include <limits>
#include <span>

#include "models/mesh.h"

namespace sylva {

// Eq. 2 as first solved: the shift that makes the triangle face the viewer; v_y = 0 gives an
// infinite shift (the reason for the limit).
float slant_shift_exact(const glm::vec3& vertex, const glm::vec3& centre, const glm::vec3& viewer);

// Eq. 2 limited by f (0: no slanting). A viewer at the centre gives 0. The shift is held within
// ±f·reach: Sylva draws far shells on coarser grids of the ground (components/shell_tile.h),
// whose triangles turned by Eq. 2 alone would stand as tall as they are wide and smear the
// slices over tens of metres; held to what a triangle of the ground's own grid (reach: the
// largest distance of its vertices from their centre) would shift, a big triangle turns less.
float slant_shift(const glm::vec3& vertex, const glm::vec3& centre, const glm::vec3& viewer, float f,
                  float reach = std::numeric_limits<float>::infinity());

// A triangle's reach: the largest distance of its vertices from their centre (a + b + c) / 3.
float triangle_reach(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// The largest triangle_reach over `tiles` (their indexed triangles): the reach slant_shift holds
// every grid to, taken on the ground's own.
float shell_slant_reach(std::span<const mesh_data> tiles);

}  // namespace sylva
