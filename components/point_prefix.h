#pragma once
// Deussen 2002 §5.3: a plant's level of detail under the point/line representation is a few
// prefix lengths into its parts' randomly ordered triangle, point and line lists
// (models/bake/point_line_model.h): per part, the first `triangles` triangles and the first
// `primitives` points or lines. Writer: update_point_prefix (Eq. 1, Eq. 2 and the blend);
// read by build_draw_list, which draws exactly these prefixes.
#include <array>
#include <cstdint>

namespace sylva {

// Parts per plant cell (bark, twigs, foliage, one important kind); the bake's
// k_max_cell_parts is static_asserted equal where both are visible.
constexpr std::size_t k_prefix_parts = 4;

struct point_prefix {
    std::array<std::uint32_t, k_prefix_parts> triangles{};
    std::array<std::uint32_t, k_prefix_parts> primitives{};  // points or lines, by the part
    // 1 when a line part draws `primitives` splats at its lines' ends instead of lines (its
    // lines are shorter than d' on screen; lod/point_line_lod.h select_lines).
    std::array<std::uint8_t, k_prefix_parts> splats{};
    // Soft splats draw a fractional prefix (lod/point_line_lod.h): a points-only part draws
    // ⌈p⌉ splats of Eq. 1's p, the last one faded out by this much, in 1/255 (its opacity is
    // p − ⌊p⌋), so the splats drawn grow continuously with p instead of a whole splat at a time.
    // 0: every splat whole.
    std::array<std::uint8_t, k_prefix_parts> last_fade{};
};
static_assert(sizeof(point_prefix) == 40);

}  // namespace sylva
