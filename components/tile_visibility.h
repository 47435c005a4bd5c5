#pragma once
// Whether an eco tile (components/tile.h) passed hierarchical culling this frame: 0 for a tile
// outside the frustum or beyond every draw distance, and for all tiles below it.
// Writer: cull; read by later per-tile work (point approximations of whole tiles).
#include <cstdint>

namespace sylva {

struct tile_visibility {
    std::uint8_t visible = 0;          // some plant of the tile may be drawn
    std::uint8_t in_shadow_range = 0;  // some plant of the tile may cast into the cascades
};
static_assert(sizeof(tile_visibility) == 2);

}  // namespace sylva
