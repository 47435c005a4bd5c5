#include "models/bake/lodf_leaves.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <map>
#include <numeric>
#include <unordered_map>

namespace sylva {
namespace {

// Union-find over vertex indices, to split the foliage into connected pieces.
struct vertex_sets {
    std::vector<std::uint32_t> parent;
    explicit vertex_sets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    std::uint32_t find(std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    }
    void unite(std::uint32_t a, std::uint32_t b) {
        a = find(a), b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

glm::vec3 triangle_cross(const std::vector<vertex>& v, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    return glm::cross(v[b].position - v[a].position, v[c].position - v[a].position);
}

void describe(const mesh_data& mesh, foliage_leaf& leaf) {
    glm::vec3 weighted{0.0f}, normal{0.0f};
    std::vector<std::uint32_t> used;
    for (const std::uint32_t t : leaf.triangles) {
        const std::uint32_t* i = &mesh.indices[3 * std::size_t(t)];
        const glm::vec3 cross = triangle_cross(mesh.vertices, i[0], i[1], i[2]);
        const float area = 0.5f * glm::length(cross);
        leaf.area += area;
        weighted += area * (mesh.vertices[i[0]].position + mesh.vertices[i[1]].position + mesh.vertices[i[2]].position) / 3.0f;
        normal += 0.5f * cross;
        used.insert(used.end(), i, i + 3);
    }
    const std::uint32_t first = mesh.indices[3 * std::size_t(leaf.triangles[0])];
    leaf.centre = leaf.area > 0.0f ? weighted / leaf.area : mesh.vertices[first].position;
    leaf.normal = glm::length(normal) > 1e-12f ? glm::normalize(normal) : glm::vec3(0.0f, 1.0f, 0.0f);
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    // Extremes in texture space, the lowest vertex index on ties.
    std::array<float, 4> best{};
    for (std::size_t k = 0; k < used.size(); ++k) {
        const glm::vec2 uv = mesh.vertices[used[k]].uv;
        const std::array<float, 4> score{-(uv.x + uv.y), uv.x - uv.y, uv.x + uv.y, uv.y - uv.x};
        for (std::size_t c = 0; c < 4; ++c)
            if (k == 0 || score[c] > best[c]) best[c] = score[c], leaf.corners[c] = used[k];
    }
    if (!mesh.parts.empty()) leaf.branch = mesh.parts[leaf.triangles[0]].branch;
}

// Interleaves the low 10 bits of x, y, z (Morton order).
std::uint32_t morton(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    std::uint32_t code = 0;
    for (std::uint32_t bit = 0; bit < 10; ++bit)
        code |= ((x >> bit) & 1u) << (3 * bit) | ((y >> bit) & 1u) << (3 * bit + 1) | ((z >> bit) & 1u) << (3 * bit + 2);
    return code;
}

// Each stem's position in a depth-first walk of the stem hierarchy (children by index).
std::unordered_map<std::uint32_t, std::uint32_t> depth_first_ranks(const mesh_data& mesh) {
    std::map<std::uint32_t, std::vector<std::uint32_t>> children;
    std::vector<std::uint32_t> roots;
    std::map<std::uint32_t, std::uint32_t> parent_of;
    for (const triangle_part& p : mesh.parts) parent_of.emplace(p.branch, p.parent_branch);
    for (const auto& [branch, parent] : parent_of) {
        if (parent == branch || !parent_of.count(parent)) roots.push_back(branch);
        else children[parent].push_back(branch);
    }
    std::unordered_map<std::uint32_t, std::uint32_t> rank;
    std::vector<std::uint32_t> stack(roots.rbegin(), roots.rend());
    while (!stack.empty()) {
        const std::uint32_t b = stack.back();
        stack.pop_back();
        if (!rank.emplace(b, std::uint32_t(rank.size())).second) continue;  // a cycle in bad data
        const auto it = children.find(b);
        if (it != children.end()) stack.insert(stack.end(), it->second.rbegin(), it->second.rend());
    }
    return rank;
}

}  // namespace

mesh_data non_foliage_part(const mesh_data& mesh, bool keep_vertices) {
    mesh_data out;
    if (keep_vertices) out.vertices = mesh.vertices;
    out.bounds_min = mesh.bounds_min;
    out.bounds_max = mesh.bounds_max;
    for (const submesh& s : mesh.submeshes) {
        if (s.material == material_kind::leaf) continue;
        out.submeshes.push_back({std::uint32_t(out.indices.size()), s.index_count, s.material});
        out.indices.insert(out.indices.end(), mesh.indices.begin() + s.first_index,
                           mesh.indices.begin() + s.first_index + s.index_count);
    }
    return out;
}

std::vector<foliage_leaf> find_foliage_leaves(const mesh_data& mesh) {
    vertex_sets sets(mesh.vertices.size());
    std::vector<std::uint32_t> triangles;
    for (const submesh& s : mesh.submeshes) {
        if (s.material != material_kind::leaf) continue;
        for (std::uint32_t t = s.first_index / 3; t < (s.first_index + s.index_count) / 3; ++t) {
            const std::uint32_t* i = &mesh.indices[3 * std::size_t(t)];
            sets.unite(i[0], i[1]);
            sets.unite(i[0], i[2]);
            triangles.push_back(t);
        }
    }
    std::sort(triangles.begin(), triangles.end());
    std::vector<foliage_leaf> leaves;
    std::unordered_map<std::uint32_t, std::uint32_t> leaf_of_set;
    for (const std::uint32_t t : triangles) {
        const std::uint32_t set = sets.find(mesh.indices[3 * std::size_t(t)]);
        const auto [it, added] = leaf_of_set.emplace(set, std::uint32_t(leaves.size()));
        if (added) leaves.emplace_back();
        leaves[it->second].triangles.push_back(t);
    }
    for (foliage_leaf& leaf : leaves) describe(mesh, leaf);
    return leaves;
}

std::vector<std::vector<std::uint32_t>> cluster_foliage_leaves(const mesh_data& mesh,
                                                               const std::vector<foliage_leaf>& leaves,
                                                               bool has_hierarchy, std::uint32_t groups) {
    std::vector<std::uint64_t> key(leaves.size());
    if (has_hierarchy && !mesh.parts.empty()) {
        const auto rank = depth_first_ranks(mesh);
        for (std::size_t i = 0; i < leaves.size(); ++i) {
            const auto it = rank.find(leaves[i].branch);
            key[i] = it == rank.end() ? 0 : it->second;
        }
    } else {
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (const foliage_leaf& l : leaves) lo = glm::min(lo, l.centre), hi = glm::max(hi, l.centre);
        const glm::vec3 extent = glm::max(hi - lo, glm::vec3(1e-6f));
        for (std::size_t i = 0; i < leaves.size(); ++i) {
            const glm::vec3 q = glm::clamp((leaves[i].centre - lo) / extent, 0.0f, 1.0f) * 1023.0f;
            key[i] = morton(std::uint32_t(q.x), std::uint32_t(q.y), std::uint32_t(q.z));
        }
    }
    std::vector<std::uint32_t> order(leaves.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    std::vector<std::vector<std::uint32_t>> clusters(groups);
    for (std::uint32_t c = 0; c < groups; ++c) {
        const std::size_t from = order.size() * c / groups, to = order.size() * (c + 1) / groups;
        clusters[c].assign(order.begin() + std::ptrdiff_t(from), order.begin() + std::ptrdiff_t(to));
    }
    return clusters;
}

float quad_area(const std::vector<vertex>& vertices, const std::array<std::uint32_t, 4>& q) {
    return 0.5f * (glm::length(triangle_cross(vertices, q[0], q[1], q[2])) +
                   glm::length(triangle_cross(vertices, q[0], q[2], q[3])));
}

namespace {

// How far quad q's area is from `target_area`, as a share of it; a folded quad (its two
// triangles facing apart) scores past any flat one.
float score_of(const std::vector<vertex>& vertices, const std::array<std::uint32_t, 4>& q, float target_area) {
    const glm::vec3 first = triangle_cross(vertices, q[0], q[1], q[2]);
    const glm::vec3 second = triangle_cross(vertices, q[0], q[2], q[3]);
    const float area = 0.5f * (glm::length(first) + glm::length(second));
    const bool folded = glm::dot(first, second) < 0.0f;
    return std::abs(area / std::max(target_area, 1e-12f) - 1.0f) + (folded ? 1e3f : 0.0f);
}

}  // namespace

std::array<std::uint32_t, 4> collapse_quad(const std::vector<vertex>& vertices, const std::array<std::uint32_t, 4>& a,
                                           const std::array<std::uint32_t, 4>& b, float target_area) {
    // Each texture corner from either leaf: 16 quads, the texture spanning each once. Ties go to
    // the lowest mask, so a quad of a's own corners (mask 0) wins only when nothing is nearer.
    std::array<std::uint32_t, 4> best = a;
    float best_score = std::numeric_limits<float>::infinity();
    for (std::uint32_t mask = 0; mask < 16; ++mask) {
        std::array<std::uint32_t, 4> q;
        for (std::uint32_t c = 0; c < 4; ++c) q[c] = (mask >> c) & 1u ? b[c] : a[c];
        const float score = score_of(vertices, q, target_area);
        if (score < best_score) best_score = score, best = q;
    }
    return best;
}

namespace {

// The rectangle a made leaf would ideally be: `target_area` about `centre` in the plane of
// `normal`, its long side along the widest spread of `candidates` (at most 4:1), corners in
// texture order (bl, br, tr, tl) for symmetry `turn` of the square (4 rotations x 2 mirrors).
std::array<glm::vec3, 4> ideal_rectangle(const std::vector<vertex>& vertices,
                                         const std::array<std::vector<std::uint32_t>, 4>& candidates, float target_area,
                                         const glm::vec3& centre, const glm::vec3& normal, int turn) {
    const glm::vec3 helper = std::abs(normal.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 e1 = glm::normalize(glm::cross(helper, normal)), e2 = glm::cross(normal, e1);
    double xx = 0.0, yy = 0.0, xy = 0.0;
    for (const auto& list : candidates)
        for (const std::uint32_t v : list) {
            const glm::vec3 d = vertices[v].position - centre;
            const double x = glm::dot(d, e1), y = glm::dot(d, e2);
            xx += x * x, yy += y * y, xy += x * y;
        }
    const double angle = 0.5 * std::atan2(2.0 * xy, xx - yy);
    const glm::vec3 u = float(std::cos(angle)) * e1 + float(std::sin(angle)) * e2, v = glm::cross(normal, u);
    double su = 0.0, sv = 0.0;
    for (const auto& list : candidates)
        for (const std::uint32_t w : list) {
            const glm::vec3 d = vertices[w].position - centre;
            su += double(glm::dot(d, u)) * glm::dot(d, u), sv += double(glm::dot(d, v)) * glm::dot(d, v);
        }
    const float aspect = float(std::clamp(std::sqrt(su / std::max(sv, 1e-12)), 1.0, 4.0));
    const float half_v = std::sqrt(target_area / (4.0f * aspect)), half_u = aspect * half_v;
    // The square's corners counter-clockwise from bottom-left, rotated and mirrored by `turn`.
    static constexpr float k_x[4] = {-1, 1, 1, -1}, k_y[4] = {-1, -1, 1, 1};
    std::array<glm::vec3, 4> out;
    for (int c = 0; c < 4; ++c) {
        const int k = (turn < 4 ? c + turn : (4 - c) + turn) % 4;
        out[std::size_t(c)] = centre + u * (k_x[k] * half_u) + v * (k_y[k] * half_v);
    }
    return out;
}

}  // namespace

std::array<std::uint32_t, 4> widen_quad(const std::vector<vertex>& vertices, std::array<std::uint32_t, 4> q,
                                        const std::array<std::vector<std::uint32_t>, 4>& candidates, float target_area,
                                        const glm::vec3& centre, const glm::vec3& normal) {
    float best = score_of(vertices, q, target_area);
    // The ideal rectangle, each corner snapped to the nearest original corner of its kind.
    for (int turn = 0; turn < 8; ++turn) {
        const std::array<glm::vec3, 4> ideal = ideal_rectangle(vertices, candidates, target_area, centre, normal, turn);
        std::array<std::uint32_t, 4> snapped = q;
        for (std::size_t c = 0; c < 4; ++c) {
            float nearest = std::numeric_limits<float>::infinity();
            for (const std::uint32_t v : candidates[c]) {
                const glm::vec3 d = vertices[v].position - ideal[c];
                if (glm::dot(d, d) < nearest) nearest = glm::dot(d, d), snapped[c] = v;
            }
        }
        const float score = score_of(vertices, snapped, target_area);
        if (score < best) best = score, q = snapped;
    }
    // Then one corner at a time while that brings the area nearer.
    constexpr int k_passes = 3;
    for (int pass = 0; pass < k_passes; ++pass) {
        bool moved = false;
        for (std::size_t c = 0; c < 4; ++c)
            for (const std::uint32_t v : candidates[c]) {
                std::array<std::uint32_t, 4> trial = q;
                trial[c] = v;
                const float score = score_of(vertices, trial, target_area);
                if (score < best) best = score, q = trial, moved = true;
            }
        if (!moved) break;
    }
    return q;
}

float append_lodf_indices(const mesh_data& mesh, const std::vector<foliage_leaf>& leaves,
                          const std::vector<std::array<std::uint32_t, 4>>& made_corners, lodf_structure& structure,
                          std::vector<std::uint32_t>& indices) {
    const std::uint32_t n = structure.leaf_count;
    std::vector<float> area(structure.nodes.size());
    for (std::uint32_t i = 0; i < n; ++i) area[i] = leaves[i].area;
    double ratio_sum = 0.0;
    for (std::uint32_t k = 0; k < structure.collapses.size(); ++k) {
        const lodf_collapse& c = structure.collapses[k];
        const std::uint32_t made = n + k;
        area[made] = area[c.old1] + area[c.old2];
        ratio_sum += area[made] > 0.0f ? quad_area(mesh.vertices, made_corners[k]) / area[made] : 1.0;
    }
    for (lodf_node& node : structure.nodes) {
        node.first_index = std::uint32_t(indices.size());
        if (node.leaf < n) {
            for (const std::uint32_t t : leaves[node.leaf].triangles)
                indices.insert(indices.end(), &mesh.indices[3 * std::size_t(t)], &mesh.indices[3 * std::size_t(t) + 3]);
        } else {
            const auto& q = made_corners[node.leaf - n];
            // Wound so its front faces the way its corners' normals do: mesh.frag turns the normal
            // of a leaf seen from behind (!gl_FrontFacing), and a made quad wound against its
            // normals is lit from the back. Wound as its corners came, broadleaf at half its
            // leaves came out visibly darker: FLIP 0.291 against the full plant, 0.225 so.
            const glm::vec3 facing = triangle_cross(mesh.vertices, q[0], q[1], q[2]) + triangle_cross(mesh.vertices, q[0], q[2], q[3]);
            const glm::vec3 normals = mesh.vertices[q[0]].normal + mesh.vertices[q[1]].normal +
                                      mesh.vertices[q[2]].normal + mesh.vertices[q[3]].normal;
            if (glm::dot(facing, normals) >= 0.0f) indices.insert(indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
            else indices.insert(indices.end(), {q[0], q[2], q[1], q[0], q[3], q[2]});
        }
        node.index_count = std::uint32_t(indices.size()) - node.first_index;
    }
    return structure.collapses.empty() ? 1.0f : float(ratio_sum / double(structure.collapses.size()));
}

}  // namespace sylva
