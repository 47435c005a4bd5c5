#pragma once
// Rebollo 2006 §3.2: the counters of one foliage cluster of a plant on the LoDF rung
// (lod/lodf.h): the binary tree under one leaf of the coarsest approximation. Its active leaves
// are the `active_leaves` consecutive entries of the cluster's array from `init_group`, one
// contiguous index range. Writer: lod/lodf.h retarget_lodf (Eq. 10–12), run by the LoDF
// system; read by the draw-list builder, which rewrites the cluster's draw command only when
// the counters changed.
#include <cstdint>

namespace sylva {

struct cluster_changes {
    std::uint32_t init_group = 0;     // array position of the first active leaf
    std::uint32_t active_leaves = 0;  // leaves drawn at the current level of detail
    // Collapses (or splits) counted for this cluster by the walk over Changed_group and not yet
    // applied; 0 between frames (§3.3: "reset to 0 ... into all the groups").
    std::uint32_t changes_number = 0;
};
static_assert(sizeof(cluster_changes) == 12);

}  // namespace sylva
