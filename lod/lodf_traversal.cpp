#include "lod/lodf_traversal.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "lod/lodf.h"

namespace sylva {
namespace {

using clock_type = std::chrono::steady_clock;

double ns_since(clock_type::time_point start) {
    return std::chrono::duration<double, std::nano>(clock_type::now() - start).count();
}

// The whole-foliage update: a flag per leaf of F^r, moved by the collapses or splits between two
// levels, then every active leaf's indices copied out in F^r's order.
class whole_foliage {
public:
    explicit whole_foliage(const lodf_model& model) : m_model(model), m_active(model.structure.nodes.size(), 0) {
        std::fill(m_active.begin(), m_active.begin() + model.structure.leaf_count, 1);
        m_slot.resize(model.structure.nodes.size());
        for (std::uint32_t i = 0; i < model.structure.nodes.size(); ++i) m_slot[model.structure.nodes[i].leaf] = i;
    }
    void move(std::uint32_t from, std::uint32_t to) {
        const lodf_structure& f = m_model.structure;
        for (std::uint32_t k = from; k < to; ++k) set(f.collapses[k], f.leaf_count + k, 0);
        for (std::uint32_t k = from; k > to; --k) set(f.collapses[k - 1], f.leaf_count + k - 1, 1);
    }
    const std::vector<std::uint32_t>& extract() {
        m_indices.clear();
        const lodf_structure& f = m_model.structure;
        for (std::uint32_t leaf = 0; leaf < m_active.size(); ++leaf) {
            if (!m_active[leaf]) continue;
            const lodf_node& n = f.nodes[m_slot[leaf]];
            m_indices.insert(m_indices.end(), m_model.indices.begin() + n.first_index,
                             m_model.indices.begin() + n.first_index + n.index_count);
        }
        return m_indices;
    }

private:
    // A collapse (originals_on = 0) or the split that undoes it (1).
    void set(const lodf_collapse& c, std::uint32_t made, char originals_on) {
        m_active[c.old1] = m_active[c.old2] = originals_on;
        m_active[made] = char(1 - originals_on);
    }
    const lodf_model& m_model;
    std::vector<char> m_active;          // by leaf number
    std::vector<std::uint32_t> m_slot;   // leaf number -> index into nodes
    std::vector<std::uint32_t> m_indices;
};

std::vector<std::uint32_t> sorted_copy(std::vector<std::uint32_t> v) {
    std::sort(v.begin(), v.end());
    return v;
}

}  // namespace

std::vector<std::uint32_t> traversal_levels(const lodf_structure& lodf, std::uint32_t steps) {
    steps = std::max<std::uint32_t>(steps, 1);
    const std::uint32_t total = lodf.collapse_count();
    std::vector<std::uint32_t> levels;
    for (std::uint32_t s = 1; s <= steps; ++s) levels.push_back(std::uint32_t(std::uint64_t(total) * s / steps));
    for (std::uint32_t s = steps; s-- > 0;) levels.push_back(std::uint32_t(std::uint64_t(total) * s / steps));
    return levels;
}

std::vector<traversal_change> traverse_lodf(const lodf_model& model, const std::vector<std::uint32_t>& levels,
                                            bool verify) {
    const lodf_structure& f = model.structure;
    std::vector<cluster_changes> clusters(f.clusters.size());
    reset_lodf_clusters(f, clusters);
    // F_0's commands, uploaded once before the traversal.
    std::vector<lodf_draw_command> commands(f.clusters.size());
    for (std::uint32_t c = 0; c < clusters.size(); ++c) {
        const lodf_range r = active_range(f, c, clusters[c]);
        commands[c].count = r.index_count;
        commands[c].first_index = r.first_index;
    }
    std::vector<std::uint32_t> changed;
    changed.reserve(f.clusters.size());
    whole_foliage whole(model);
    std::uint32_t lodf_position = 0, whole_position = 0;
    std::vector<traversal_change> out;
    std::vector<std::uint32_t> lodf_drawn;
    for (const std::uint32_t level : levels) {
        traversal_change change;
        auto start = clock_type::now();
        retarget_lodf(f, clusters, lodf_position, level, changed);
        for (const std::uint32_t c : changed) {
            const lodf_range r = active_range(f, c, clusters[c]);
            commands[c].count = r.index_count;
            commands[c].first_index = r.first_index;
        }
        change.lodf_ns = ns_since(start);
        change.clusters_changed = std::uint32_t(changed.size());
        change.lodf_bytes = changed.size() * sizeof(lodf_draw_command);
        start = clock_type::now();
        whole.move(whole_position, level);
        whole_position = level;
        const std::vector<std::uint32_t>& indices = whole.extract();
        change.whole_ns = ns_since(start);
        change.whole_bytes = indices.size() * sizeof(std::uint32_t);
        change.leaves = f.leaves_after(level);
        out.push_back(change);
        if (!verify) continue;
        // Both draw the same triangles.
        lodf_drawn.clear();
        for (const lodf_draw_command& c : commands)
            lodf_drawn.insert(lodf_drawn.end(), model.indices.begin() + c.first_index,
                              model.indices.begin() + c.first_index + c.count);
        if (sorted_copy(lodf_drawn) != sorted_copy(indices))
            throw std::logic_error("LoDF traversal: the clusters' ranges and the whole extraction differ at " +
                                   std::to_string(level) + " collapses");
    }
    return out;
}

}  // namespace sylva
