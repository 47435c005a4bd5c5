#pragma once
// LoDF's multiresolution structure F^r (Rebollo, Remolar, Chover, Ripollés 2006, "An efficient
// continuous level of detail model for foliage", §3.1–3.2) as the bake makes it
// (models/bake/lodf_bake.h) and the bake cache stores it; the runtime's retrieval algorithms
// (§3.3) are lod/lodf.h.
//
// F^r (§3.1–3.2). Every collapse (Eq. 1) turns two leaves into a new one, numbered after the
// originals in collapse order (l_L is made by the first collapse). The leaves form a forest of
// binary trees whose roots are the coarsest approximation F_{n-1}; the leaves of one tree are a
// cluster, stored as one array. Changed_group (Figure 8) lists the cluster of each collapse, in
// the order the collapses are made; init_position is how many of them a plant has made.
//
// Why each cluster is a FIFO. Eq. 10 moves a cluster's first active leaf two places per collapse
// and Eq. 11 shortens its active run by one, so the run is a window that loses its first two
// leaves and gains the next one behind it: the array must be the order a queue would hold the
// leaves in, originals first, and each collapse must take the two leaves at the queue's front.
// Given the originals' order, the tree is therefore fixed: collapse j of a cluster joins array
// positions 2j and 2j + 1 into position L_c + j. The paper's Figure 7 instead keeps its Figure 4
// trees and adds `next` links, which cannot serve every level of a chain-shaped tree: in its
// group 1 (l5 l6 l4 l10 l3 l12 l14, next 1 2 4 5 3 6 -1), after l4 and l10 collapse into l12 the
// run starts at l3 and its link leads to the removed l10, not to l12; no one set of links serves
// all four levels of that tree. Here the bake builds each cluster's tree in the queue's shape
// (models/bake/lodf_bake.h), so the active leaves are always one contiguous index range, one
// draw command per cluster, with no links to follow.
#include <cstdint>
#include <span>
#include <vector>

namespace sylva {

// One cluster's array of leaves, Figure 7.
struct lodf_cluster {
    std::uint32_t first_node = 0;       // into lodf_structure::nodes
    std::uint32_t original_leaves = 0;  // L_c, active at F_0; the array holds 2·L_c − 1 leaves
    std::uint32_t node_count() const { return 2 * original_leaves - 1; }
};

// A leaf of F^r as stored in its cluster's array: its number and where its triangles are.
struct lodf_node {
    std::uint32_t leaf = 0;  // l_i: originals 0 .. L − 1, then L + k for collapse k
    // Its triangles in the foliage's index list. The leaves of a cluster are stored back to back
    // in array order, so an active run is one index range.
    std::uint32_t first_index = 0;
    std::uint32_t index_count = 0;
};

// Eq. 1: Collapse(old1, old2) = l_new, with l_new = L + k for the k-th collapse.
struct lodf_collapse {
    std::uint32_t old1 = 0;
    std::uint32_t old2 = 0;
};

struct lodf_structure {
    std::uint32_t leaf_count = 0;                // L, the leaves of F_0
    std::vector<lodf_cluster> clusters;          // G
    std::vector<lodf_node> nodes;                // the clusters' arrays back to back: 2L − G
    std::vector<std::uint32_t> changed_group;    // Figure 8: L − G entries
    std::vector<lodf_collapse> collapses;        // the same order: L − G
    // Where leaf l_i sits: its cluster and its position in the cluster's array.
    std::vector<std::uint32_t> cluster_of_leaf;  // 2L − G
    std::vector<std::uint32_t> position_of_leaf;

    std::uint32_t collapse_count() const { return std::uint32_t(changed_group.size()); }
    // Leaves drawn after `collapses` collapses: each removes two and adds one.
    std::uint32_t leaves_after(std::uint32_t made) const { return leaf_count - made; }
};

// §3.1: F^r from each cluster's original leaves in queue order (`queues[c]`, leaf numbers
// 0 .. L − 1, each exactly once over all clusters) and the Changed_group sequence, which must
// name each cluster c exactly L_c − 1 times. Collapses are numbered in Changed_group order and
// each takes its cluster's next two queued leaves. Index ranges are left 0 for the bake to fill.
// Throws std::invalid_argument naming the leaf, cluster or collapse that breaks a rule.
lodf_structure lay_out_lodf(std::uint32_t leaf_count, std::span<const std::vector<std::uint32_t>> queues,
                            std::span<const std::uint32_t> changed_group);

}  // namespace sylva
