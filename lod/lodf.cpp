#include "lod/lodf.h"

#include "models/bake/lodf_leaves.h"

#include <algorithm>

namespace sylva {

void reset_lodf_clusters(const lodf_structure& lodf, std::span<cluster_changes> clusters) {
    for (std::size_t c = 0; c < clusters.size() && c < lodf.clusters.size(); ++c)
        clusters[c] = {0, lodf.clusters[c].original_leaves, 0};
}

void count_lodf_changes(const lodf_structure& lodf, std::span<cluster_changes> clusters, std::uint32_t from,
                        std::uint32_t to) {
    const std::uint32_t first = std::min(from, to), last = std::max(from, to);
    for (std::uint32_t k = first; k < last; ++k) ++clusters[lodf.changed_group[k]].changes_number;
}

std::uint32_t apply_lodf_changes(std::span<cluster_changes> clusters, bool reduce, std::vector<std::uint32_t>& changed) {
    changed.clear();
    // In cluster order, so `changed` is sorted without a sort.
    for (std::uint32_t c = 0; c < clusters.size(); ++c) {
        cluster_changes& s = clusters[c];
        if (s.changes_number == 0) continue;
        if (reduce) {
            s.init_group += 2 * s.changes_number;  // Eq. 10: each collapse drops two leaves...
            s.active_leaves -= s.changes_number;   // Eq. 11: ...and adds one
        } else {
            s.init_group -= 2 * s.changes_number;  // Eq. 12
            s.active_leaves += s.changes_number;   // Eq. 13: each split adds one leaf
        }
        s.changes_number = 0;
        changed.push_back(c);
    }
    return std::uint32_t(changed.size());
}

std::uint32_t retarget_lodf(const lodf_structure& lodf, std::span<cluster_changes> clusters,
                            std::uint32_t& init_position, std::uint32_t target,
                            std::vector<std::uint32_t>& changed) {
    target = std::min(target, lodf.collapse_count());
    count_lodf_changes(lodf, clusters, init_position, target);
    const bool reduce = target > init_position;
    init_position = target;
    return apply_lodf_changes(clusters, reduce, changed);
}

lodf_range active_range(const lodf_structure& lodf, std::uint32_t cluster, const cluster_changes& state) {
    if (state.active_leaves == 0) return {};
    const std::uint32_t base = lodf.clusters[cluster].first_node;
    const lodf_node& first = lodf.nodes[base + state.init_group];
    const lodf_node& last = lodf.nodes[base + state.init_group + state.active_leaves - 1];
    return {first.first_index, last.first_index + last.index_count - first.first_index};
}

std::vector<std::uint32_t> active_leaves_of(const lodf_structure& lodf, std::uint32_t cluster,
                                            const cluster_changes& state) {
    std::vector<std::uint32_t> out;
    const std::uint32_t base = lodf.clusters[cluster].first_node + state.init_group;
    for (std::uint32_t i = 0; i < state.active_leaves; ++i) out.push_back(lodf.nodes[base + i].leaf);
    return out;
}

std::uint32_t collapses_for_leaves(const lodf_structure& lodf, std::uint32_t leaves) {
    const std::uint32_t floor = lodf.leaf_count - lodf.collapse_count();
    leaves = std::clamp(leaves, floor, lodf.leaf_count);
    return lodf.leaf_count - leaves;
}

mesh_data lodf_mesh(const mesh_data& full, const lodf_model& model, std::uint32_t leaves) {
    mesh_data out = non_foliage_part(full);
    const lodf_structure& f = model.structure;
    if (f.leaf_count == 0) return out;
    std::vector<cluster_changes> clusters(f.clusters.size());
    reset_lodf_clusters(f, clusters);
    std::uint32_t position = 0;
    std::vector<std::uint32_t> changed;
    retarget_lodf(f, clusters, position, collapses_for_leaves(f, leaves), changed);
    const auto first = std::uint32_t(out.indices.size());
    for (std::uint32_t c = 0; c < clusters.size(); ++c) {
        const lodf_range r = active_range(f, c, clusters[c]);
        out.indices.insert(out.indices.end(), model.indices.begin() + r.first_index,
                           model.indices.begin() + r.first_index + r.index_count);
    }
    out.submeshes.push_back({first, std::uint32_t(out.indices.size()) - first, material_kind::leaf});
    return out;
}

}  // namespace sylva
