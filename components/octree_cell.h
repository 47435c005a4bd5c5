#pragma once
// Deussen 2002 §6.1: a big plant is split by a shallow octree so that "the content of nearby
// cells is shown polygonally while distant cells can be approximated". Each cell of each such
// plant is an entity of its own, so its level of detail is chosen on its own. Only plants of
// species baked with an octree (species_entry::cell_count > 1) have cells.
#include <cstdint>

#include "components/point_prefix.h"

namespace sylva {

// Which plant and which of its species' cells. Writer: scenario spawning (static afterwards).
struct octree_cell {
    std::uint32_t plant = 0;  // dense index of the plant in the aligned plant tables
    std::uint32_t cell = 0;   // index into species_library::cells
};
static_assert(sizeof(octree_cell) == 8);

// The cell's prefixes this frame, as point_prefix is a whole plant's. Writer:
// update_point_prefix; read by build_draw_list.
struct cell_prefix {
    point_prefix prefix;
};
static_assert(sizeof(cell_prefix) == 40);

}  // namespace sylva
