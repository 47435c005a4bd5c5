#include "models/bake/lodf_structure.h"

#include <stdexcept>
#include <string>

namespace sylva {
namespace {

[[noreturn]] void reject(const std::string& what) { throw std::invalid_argument("LoDF layout: " + what); }

}  // namespace

lodf_structure lay_out_lodf(std::uint32_t leaf_count, std::span<const std::vector<std::uint32_t>> queues,
                            std::span<const std::uint32_t> changed_group) {
    lodf_structure out;
    out.leaf_count = leaf_count;
    const auto groups = std::uint32_t(queues.size());
    if (leaf_count == 0 || groups == 0) reject("no leaves");
    if (changed_group.size() != std::size_t(leaf_count) - groups)
        reject(std::to_string(changed_group.size()) + " collapses for " + std::to_string(leaf_count) +
               " leaves in " + std::to_string(groups) + " clusters (L − G = " +
               std::to_string(leaf_count - groups) + ")");
    const std::size_t total = 2 * std::size_t(leaf_count) - groups;
    out.cluster_of_leaf.assign(total, ~0u);
    out.position_of_leaf.assign(total, ~0u);
    out.clusters.resize(groups);
    out.nodes.resize(total);
    std::uint32_t first = 0;
    for (std::uint32_t c = 0; c < groups; ++c) {
        const std::vector<std::uint32_t>& queue = queues[c];
        if (queue.empty()) reject("cluster " + std::to_string(c) + " has no leaves");
        out.clusters[c] = {first, std::uint32_t(queue.size())};
        for (std::uint32_t p = 0; p < queue.size(); ++p) {
            const std::uint32_t leaf = queue[p];
            if (leaf >= leaf_count) reject("leaf " + std::to_string(leaf) + " in cluster " + std::to_string(c) + " is not an original");
            if (out.cluster_of_leaf[leaf] != ~0u) reject("leaf " + std::to_string(leaf) + " is queued twice");
            out.cluster_of_leaf[leaf] = c;
            out.position_of_leaf[leaf] = p;
            out.nodes[first + p].leaf = leaf;
        }
        first += out.clusters[c].node_count();
    }
    // Each collapse takes its cluster's next two queued leaves (the FIFO of lod/lodf.h).
    std::vector<std::uint32_t> made(groups, 0);
    out.changed_group.assign(changed_group.begin(), changed_group.end());
    out.collapses.resize(changed_group.size());
    for (std::uint32_t k = 0; k < changed_group.size(); ++k) {
        const std::uint32_t c = changed_group[k];
        if (c >= groups) reject("collapse " + std::to_string(k) + " names cluster " + std::to_string(c));
        const lodf_cluster& cluster = out.clusters[c];
        const std::uint32_t j = made[c]++;
        if (j + 1 >= cluster.original_leaves)
            reject("cluster " + std::to_string(c) + " of " + std::to_string(cluster.original_leaves) +
                   " leaves is named by more than " + std::to_string(cluster.original_leaves - 1) + " collapses");
        const std::uint32_t made_leaf = leaf_count + k;
        const std::uint32_t position = cluster.original_leaves + j;
        out.collapses[k] = {out.nodes[cluster.first_node + 2 * j].leaf, out.nodes[cluster.first_node + 2 * j + 1].leaf};
        out.nodes[cluster.first_node + position].leaf = made_leaf;
        out.cluster_of_leaf[made_leaf] = c;
        out.position_of_leaf[made_leaf] = position;
    }
    return out;
}

}  // namespace sylva
