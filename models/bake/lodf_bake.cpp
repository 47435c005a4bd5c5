#include "models/bake/lodf_bake.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>
#include <queue>
#include <stdexcept>

#include "models/bake/lodf_leaves.h"
#include "models/bake/nanoflann_points.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_none = std::numeric_limits<std::uint32_t>::max();

// A leaf of one cluster's tree while it is built: an original (local ids 0 .. L_c − 1) or made by
// a collapse, with the area, centre, facing and texture corners the matching compares.
struct tree_node {
    float area = 0.0f;
    std::array<std::uint32_t, 4> corners{};
    // Each texture corner of the originals under it (a sample when there are many): where
    // widen_quad may move the corners of the quad it is made into.
    std::array<std::vector<std::uint32_t>, 4> reach;
    glm::vec3 centre{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    std::array<std::uint32_t, 2> child{k_none, k_none};
    std::uint32_t parent = k_none;
    float cost = 0.0f;  // of the collapse that made it
};

// The vertices the leaves' corners index (the plant's full mesh).
struct tree_nodes {
    const std::vector<vertex>* vertices = nullptr;
    std::vector<tree_node> nodes;
    tree_node& operator[](std::size_t i) { return nodes[i]; }
    const tree_node& operator[](std::size_t i) const { return nodes[i]; }
    std::size_t size() const { return nodes.size(); }
};

float pair_cost(const tree_nodes& nodes, std::uint32_t i, std::uint32_t j, std::array<std::uint32_t, 4>* quad = nullptr) {
    const tree_node& a = nodes[i];
    const tree_node& b = nodes[j];
    const std::array<std::uint32_t, 4> q = collapse_quad(*nodes.vertices, a.corners, b.corners, a.area + b.area);
    if (quad) *quad = q;
    return lodf_collapse_cost(a.area, a.centre, a.normal, b.area, b.centre, b.normal, quad_area(*nodes.vertices, q));
}

// Corners a made leaf may reach for, per texture corner: enough to span its subtree, few enough
// that widening stays linear in the leaves.
constexpr std::size_t k_reach_per_corner = 32;

std::uint32_t merge(tree_nodes& nodes, std::uint32_t a, std::uint32_t b) {
    tree_node m;
    m.cost = pair_cost(nodes, a, b, &m.corners);
    const tree_node& na = nodes[a];
    const tree_node& nb = nodes[b];
    m.area = na.area + nb.area;
    for (std::size_t c = 0; c < 4; ++c) {
        std::vector<std::uint32_t>& reach = m.reach[c];
        reach = na.reach[c];
        reach.insert(reach.end(), nb.reach[c].begin(), nb.reach[c].end());
        // Every other one when too many: still spread over the whole subtree.
        if (reach.size() > k_reach_per_corner) {
            std::vector<std::uint32_t> half;
            for (std::size_t i = 0; i < reach.size(); i += 2) half.push_back(reach[i]);
            reach = std::move(half);
        }
    }
    const float wa = m.area > 0.0f ? na.area / m.area : 0.5f;
    m.centre = na.centre * wa + nb.centre * (1.0f - wa);
    // The faces' mean, the smaller turned to agree with the larger (leaves are two-sided).
    const glm::vec3 nb_agreeing = glm::dot(na.normal, nb.normal) < 0.0f ? -nb.normal : nb.normal;
    const glm::vec3 sum = na.normal * na.area + nb_agreeing * nb.area;
    m.normal = glm::length(sum) > 1e-12f ? glm::normalize(sum) : na.normal;
    m.corners = widen_quad(*nodes.vertices, m.corners, m.reach, m.area, m.centre, m.normal);
    m.child = {a, b};
    const auto id = std::uint32_t(nodes.size());
    nodes.nodes.push_back(m);
    nodes[a].parent = id;
    nodes[b].parent = id;
    return id;
}

// Pairs `members` greedily by least cost: every member's k nearest (nanoflann) give the
// candidate pairs, taken cheapest first while both ends are free; the members left unpaired
// are paired again among themselves the same way until at most one is left. Ties break on the
// ids, so the result does not depend on anything but the input.
std::vector<std::array<std::uint32_t, 2>> greedy_pairs(const tree_nodes& nodes,
                                                       std::vector<std::uint32_t> members) {
    std::vector<std::array<std::uint32_t, 2>> pairs;
    std::vector<glm::vec3> centres;
    while (members.size() >= 2) {
        centres.clear();
        for (const std::uint32_t m : members) centres.push_back(nodes[m].centre);
        const nanoflann_points cloud{&centres};
        point_kd_tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
        tree.buildIndex();
        const std::size_t k = std::min<std::size_t>(k_lodf_neighbours + 1, members.size());
        std::vector<std::uint32_t> found(k);
        std::vector<float> d2(k);
        struct candidate {
            float cost;
            std::uint32_t a, b;
        };
        std::vector<candidate> candidates;
        for (std::size_t i = 0; i < members.size(); ++i) {
            const std::size_t n = tree.knnSearch(&centres[i].x, k, found.data(), d2.data());
            for (std::size_t f = 0; f < n; ++f) {
                if (found[f] <= i) continue;  // each pair once, never a member with itself
                candidates.push_back({pair_cost(nodes, members[i], members[found[f]]), std::uint32_t(i),
                                      std::uint32_t(found[f])});
            }
        }
        std::sort(candidates.begin(), candidates.end(), [](const candidate& x, const candidate& y) {
            return x.cost != y.cost ? x.cost < y.cost : (x.a != y.a ? x.a < y.a : x.b < y.b);
        });
        std::vector<char> taken(members.size(), 0);
        for (const candidate& c : candidates) {
            if (taken[c.a] || taken[c.b]) continue;
            taken[c.a] = taken[c.b] = 1;
            pairs.push_back({members[c.a], members[c.b]});
        }
        std::vector<std::uint32_t> left;
        for (std::size_t i = 0; i < members.size(); ++i)
            if (!taken[i]) left.push_back(members[i]);
        if (left.size() == members.size()) break;  // cannot happen: the cheapest candidate is free
        members = std::move(left);
    }
    return pairs;
}

// The member of `among` (other than `self`) that collapses with `self` at least cost.
std::uint32_t best_partner(const tree_nodes& nodes, std::uint32_t self, const std::vector<std::uint32_t>& among) {
    std::uint32_t best = k_none;
    float best_cost = std::numeric_limits<float>::infinity();
    for (const std::uint32_t m : among) {
        if (m == self) continue;
        const float c = pair_cost(nodes, self, m);
        if (c < best_cost) best_cost = c, best = m;
    }
    return best;
}

// One round of a cluster's tree: the leaves it starts from, the leaves it made (in the order
// they were made) and the one it left unpaired.
struct tree_round {
    std::vector<std::uint32_t> made;
    std::uint32_t leftover = k_none;
};

// A cluster's tree in the queue's shape (lod/lodf.h), returned as the originals' queue order.
// The queue works in rounds: round r + 1 holds round r's unpaired leaf u_r, then the leaves
// round r made in the order it made them, and pairs them front to back. So u_r must pair with
// the first leaf round r made, which is the parent of round r's front leaf F_r; and F_r must not
// be the one left unpaired. Each round is the greedy pairing under those two constraints; the
// front leaves, free until a constraint names one, are then fixed, and the rounds are ordered
// from the root down so every pair sits where the queue will take it.
std::vector<std::uint32_t> build_cluster_tree(tree_nodes& nodes, std::uint32_t originals) {
    std::vector<std::uint32_t> current(originals);
    std::iota(current.begin(), current.end(), 0u);
    if (originals == 1) return current;
    std::vector<tree_round> rounds;
    std::vector<std::uint32_t> front;  // F_r per round; k_none while free
    // Fixes the free front leaves of rounds ≤ r down a chain of first children from `node`.
    const auto fix_fronts = [&](std::size_t r, std::uint32_t node) {
        for (std::size_t k = r + 1; k-- > 0;) {
            if (front[k] != k_none) break;
            front[k] = node;
            node = nodes[node].child[0];
        }
    };
    std::uint32_t carried = k_none;  // u_{r-1}
    while (current.size() > 1) {
        const std::size_t r = rounds.size();
        front.push_back(k_none);
        tree_round round;
        std::vector<std::array<std::uint32_t, 2>> pairs;
        std::vector<std::uint32_t> rest;
        if (carried != k_none) {
            // u_{r-1} pairs with the parent of F_{r-1}: a fixed leaf, or the best one if free.
            std::uint32_t partner = front[r - 1] != k_none ? nodes[front[r - 1]].parent : k_none;
            if (partner == k_none) {
                partner = best_partner(nodes, carried, current);
                fix_fronts(r - 1, nodes[partner].child[0]);
            }
            pairs.push_back({carried, partner});
            front[r] = carried;
            for (const std::uint32_t m : current)
                if (m != carried && m != partner) rest.push_back(m);
        } else {
            if (r > 0 && front[r - 1] != k_none) front[r] = nodes[front[r - 1]].parent;
            rest = current;
        }
        std::vector<std::array<std::uint32_t, 2>> greedy = greedy_pairs(nodes, rest);
        std::vector<char> paired(nodes.size(), 0);
        for (const auto& p : greedy) paired[p[0]] = paired[p[1]] = 1;
        for (const std::uint32_t m : rest)
            if (!paired[m]) round.leftover = m;
        if (round.leftover != k_none && round.leftover == front[r]) {
            // F_r must be taken this round: it takes the greedy pair member it suits best, whose
            // old partner is left over instead.
            std::vector<std::uint32_t> candidates;
            for (const auto& p : greedy) candidates.insert(candidates.end(), {p[0], p[1]});
            const std::uint32_t partner = best_partner(nodes, front[r], candidates);
            for (auto& p : greedy)
                if (p[0] == partner || p[1] == partner) {
                    round.leftover = p[0] == partner ? p[1] : p[0];
                    p = {front[r], partner};
                    break;
                }
        }
        pairs.insert(pairs.end(), greedy.begin(), greedy.end());
        for (const auto& p : pairs) round.made.push_back(merge(nodes, p[0], p[1]));
        carried = round.leftover;
        current.clear();
        if (carried != k_none) current.push_back(carried);
        current.insert(current.end(), round.made.begin(), round.made.end());
        rounds.push_back(std::move(round));
    }
    // The last round made the root; a front still free starts the chain down from it.
    fix_fronts(rounds.size() - 1, nodes[current[0]].child[0]);
    // Root down: each round's order is its pairs in the order the next round holds what they
    // made, its front leaf first, its unpaired leaf last.
    std::vector<std::uint32_t> order{current[0]};
    for (std::size_t r = rounds.size(); r-- > 0;) {
        std::vector<std::uint32_t> below;
        for (const std::uint32_t m : order) {
            if (m == rounds[r].leftover) continue;
            std::array<std::uint32_t, 2> c = nodes[m].child;
            if (c[1] == front[r]) std::swap(c[0], c[1]);
            below.insert(below.end(), c.begin(), c.end());
        }
        if (rounds[r].leftover != k_none) below.push_back(rounds[r].leftover);
        if (below.front() != front[r]) throw std::logic_error("LoDF bake: a round's front leaf is not first");
        order = std::move(below);
    }
    return order;
}

// Merges the clusters' collapse sequences into Changed_group, cheapest first: a cluster's next
// collapse is keyed by the largest cost of its collapses so far, so each cluster's own order (the
// queue's) is kept while the clusters interleave by cost. Ties go to the lower cluster.
std::vector<std::uint32_t> merge_sequences(const std::vector<std::vector<float>>& costs) {
    using entry = std::pair<float, std::uint32_t>;
    std::priority_queue<entry, std::vector<entry>, std::greater<entry>> next;
    std::vector<std::size_t> taken(costs.size(), 0);
    std::vector<float> key(costs.size(), 0.0f);
    for (std::uint32_t c = 0; c < costs.size(); ++c)
        if (!costs[c].empty()) next.push({key[c] = costs[c][0], c});
    std::vector<std::uint32_t> sequence;
    while (!next.empty()) {
        const std::uint32_t c = next.top().second;
        next.pop();
        sequence.push_back(c);
        if (++taken[c] < costs[c].size()) next.push({key[c] = std::max(key[c], costs[c][taken[c]]), c});
    }
    return sequence;
}

}  // namespace

float lodf_collapse_cost(float a, const glm::vec3& ca, const glm::vec3& na, float b, const glm::vec3& cb,
                         const glm::vec3& nb, float q) {
    const float total = a + b;
    if (total <= 0.0f) return 0.0f;
    const float side = std::sqrt(total);
    const float moved = 2.0f * a * b / total * glm::length(ca - cb);
    const float turned = total * side * (1.0f - std::abs(glm::dot(na, nb)));
    const float resized = std::abs(q - total) * side;
    return moved + turned + resized;
}

lodf_model bake_lodf(const mesh_data& full, bool has_hierarchy, const lodf_settings& settings) {
    lodf_model out;
    out.vertex_count = std::uint32_t(full.vertices.size());
    const std::vector<foliage_leaf> leaves = find_foliage_leaves(full);
    const auto leaf_count = std::uint32_t(leaves.size());
    if (leaf_count == 0) return out;
    std::vector<char> in_crown(full.vertices.size(), 0);
    for (const foliage_leaf& leaf : leaves)
        for (const std::uint32_t t : leaf.triangles)
            for (int k = 0; k < 3; ++k) in_crown[full.indices[3 * std::size_t(t) + std::size_t(k)]] = 1;
    out.crown_vertices = std::uint32_t(std::count(in_crown.begin(), in_crown.end(), 1));
    const std::uint32_t groups = std::clamp<std::uint32_t>(
        settings.clusters ? settings.clusters
                          : (leaf_count + std::max(settings.leaves_per_cluster, 1u) - 1) / std::max(settings.leaves_per_cluster, 1u),
        1,
        leaf_count);
    const std::vector<std::vector<std::uint32_t>> members = cluster_foliage_leaves(full, leaves, has_hierarchy, groups);
    std::vector<std::vector<std::uint32_t>> queues(groups);
    std::vector<std::vector<float>> costs(groups);
    std::vector<std::vector<std::array<std::uint32_t, 4>>> made_corners(groups);  // by collapse of the cluster
    for (std::uint32_t c = 0; c < groups; ++c) {
        tree_nodes nodes{&full.vertices, {}};
        for (const std::uint32_t leaf : members[c]) {
            tree_node n;
            n.corners = leaves[leaf].corners;
            for (std::size_t k = 0; k < 4; ++k) n.reach[k] = {n.corners[k]};
            n.area = leaves[leaf].area;
            n.centre = leaves[leaf].centre;
            n.normal = leaves[leaf].normal;
            nodes.nodes.push_back(n);
        }
        const std::vector<std::uint32_t> local = build_cluster_tree(nodes, std::uint32_t(members[c].size()));
        for (const std::uint32_t l : local) queues[c].push_back(members[c][l]);
        // The queue's collapses in order: collapse j joins positions 2j and 2j + 1.
        std::vector<std::uint32_t> array = local;
        for (std::size_t j = 0; j + 1 < members[c].size(); ++j) {
            const std::uint32_t made = nodes[array[2 * j]].parent;
            if (made == k_none || nodes[array[2 * j + 1]].parent != made)
                throw std::logic_error("LoDF bake: a cluster's tree is not in the queue's shape");
            costs[c].push_back(nodes[made].cost);
            made_corners[c].push_back(nodes[made].corners);
            array.push_back(made);
        }
    }
    out.structure = lay_out_lodf(leaf_count, queues, merge_sequences(costs));
    // The made leaves' quads in Changed_group order: collapse k is its cluster's next one.
    std::vector<std::array<std::uint32_t, 4>> corners;
    std::vector<std::size_t> taken(groups, 0);
    for (const std::uint32_t c : out.structure.changed_group) corners.push_back(made_corners[c][taken[c]++]);
    out.mean_area_ratio = append_lodf_indices(full, leaves, corners, out.structure, out.indices);
    return out;
}

lodf_storage lodf_storage_of(const lodf_model& model) {
    const lodf_structure& s = model.structure;
    lodf_storage out;
    // Eq. 7 and 8: 3 words per vertex, 6 per leaf of F^r, 3 per cluster, 1 per collapse.
    out.words = 3ull * model.crown_vertices + 6ull * s.nodes.size() + 3ull * s.clusters.size() + s.changed_group.size();
    out.eq9_words = 6.25 * double(model.crown_vertices);
    out.bytes = s.nodes.size() * sizeof(lodf_node) + s.clusters.size() * sizeof(lodf_cluster) +
                s.changed_group.size() * sizeof(std::uint32_t) + model.indices.size() * sizeof(std::uint32_t);
    return out;
}

}  // namespace sylva
