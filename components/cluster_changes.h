#pragma once
// Rebollo 2006 (LoDF) per-cluster counters: the cluster's leaves live in a level-ordered array;
// `init_group` is the first active leaf, `active_leaves` how many are drawn, `changes_number`
// the collapses applied since the last upload (collapse: init_group += 2·changes). Only clusters
// whose counters changed are re-uploaded. Defined now; the LoDF issue writes and reads them.
#include <cstdint>

namespace sylva {

struct cluster_changes {
    std::uint32_t init_group = 0;
    std::uint32_t active_leaves = 0;
    std::int32_t changes_number = 0;
    std::uint32_t init_position = 0;  // offset of the cluster in the Changed_group sequence
};
static_assert(sizeof(cluster_changes) == 16);

}  // namespace sylva
