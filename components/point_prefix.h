#pragma once
// Deussen 2002 §5.3: a plant's level of detail is a few prefix lengths into its randomly
// ordered triangle, point and line lists. `points` is p from Eq. 1 (the triangle count follows
// from p and the blend rule), `lines` is q·n_l from Eq. 2. Writer: select_representation (the
// point/line LOD work); read by build_draw_list. Defined now, filled by the point/line issue.
#include <cstdint>

namespace sylva {

struct point_prefix {
    std::uint32_t points = 0;
    std::uint32_t lines = 0;
};
static_assert(sizeof(point_prefix) == 8);

}  // namespace sylva
