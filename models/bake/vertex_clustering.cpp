#include "models/bake/vertex_clustering.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <stdexcept>
#include <string>

#include "models/random.h"
#include "ecs/parallel.h"

namespace sylva {
std::vector<std::uint32_t> triangle_vertices(const mesh_data& mesh, std::span<const std::uint32_t> triangles) {
    std::vector<std::uint32_t> vertices;
    vertices.reserve(triangles.size() * 3);
    for (std::uint32_t t : triangles)
        for (int c = 0; c < 3; ++c) vertices.push_back(mesh.indices[std::size_t(t) * 3 + std::size_t(c)]);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    return vertices;
}

namespace {

// Points per task of the parallel assignment step; labels do not depend on it.
constexpr std::size_t k_assign_grain = 4096;

// Per triangle: drawn as foliage (leaf, billboard), as bark (bark, ground), or not at all.
enum class triangle_kind : std::uint8_t { none, bark, foliage };

std::vector<triangle_kind> kinds_of(const mesh_data& mesh) {
    std::vector<triangle_kind> kinds(mesh.triangle_count(), triangle_kind::none);
    for (const submesh& sub : mesh.submeshes) {
        const bool foliage = sub.material == material_kind::leaf || sub.material == material_kind::billboard;
        const std::size_t end = std::min<std::size_t>((std::size_t(sub.first_index) + sub.index_count) / 3, kinds.size());
        for (std::size_t t = sub.first_index / 3; t < end; ++t)
            kinds[t] = foliage ? triangle_kind::foliage : triangle_kind::bark;
    }
    return kinds;
}

// Renumbers labels 0..n-1 in order of first appearance, leaving k_no_cluster alone; returns n.
std::uint32_t compact(std::vector<std::uint32_t>& labels) {
    std::map<std::uint32_t, std::uint32_t> renumber;
    for (std::uint32_t& label : labels) {
        if (label == k_no_cluster) continue;
        const auto [it, inserted] = renumber.emplace(label, std::uint32_t(renumber.size()));
        label = it->second;
    }
    return std::uint32_t(renumber.size());
}

double distance2(const glm::dvec3& a, const glm::vec3& b) {
    const glm::dvec3 d = a - glm::dvec3(b);
    return glm::dot(d, d);
}

// k-means++ (Arthur & Vassilvitskii 2007): the first centre uniformly, each next one with
// probability proportional to the squared distance to the nearest centre so far. Stops early
// when every point already sits on a centre.
std::vector<glm::dvec3> seed_centres(std::span<const glm::vec3> points, std::uint32_t k, rng& random) {
    std::vector<glm::dvec3> centres{glm::dvec3(points[random.below(std::uint32_t(points.size()))])};
    std::vector<double> nearest(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) nearest[i] = distance2(centres[0], points[i]);
    while (centres.size() < k) {
        double total = 0.0;
        for (double d : nearest) total += d;
        if (!(total > 0.0)) break;
        const double pick = random.uniform_double() * total;
        double running = 0.0;
        std::size_t chosen = points.size() - 1;
        for (std::size_t i = 0; i < points.size(); ++i) {
            running += nearest[i];
            if (running > pick && nearest[i] > 0.0) {
                chosen = i;
                break;
            }
        }
        while (nearest[chosen] == 0.0) --chosen;  // rounding at the very end of the scan
        centres.emplace_back(points[chosen]);
        for (std::size_t i = 0; i < points.size(); ++i)
            nearest[i] = std::min(nearest[i], distance2(centres.back(), points[i]));
    }
    return centres;
}

// Nearest centre per point (ties to the lower index); true when a label changed.
bool assign(std::span<const glm::vec3> points, const std::vector<glm::dvec3>& centres, std::vector<std::uint32_t>& labels) {
    std::vector<std::uint8_t> changed(points.size(), 0);
    ecs::parallel_for(points.size(), k_assign_grain, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t i = begin; i < end; ++i) {
            std::uint32_t best = 0;
            double best_d = distance2(centres[0], points[i]);
            for (std::uint32_t c = 1; c < centres.size(); ++c) {
                const double d = distance2(centres[c], points[i]);
                if (d < best_d) best_d = d, best = c;
            }
            changed[i] = labels[i] != best;
            labels[i] = best;
        }
    });
    return std::any_of(changed.begin(), changed.end(), [](std::uint8_t c) { return c != 0; });
}

// A triangle's cluster from its vertices' labels: the majority, else the first vertex's.
std::uint32_t vote(std::uint32_t a, std::uint32_t b, std::uint32_t c) { return (b == c && a != b) ? b : a; }

// k-means on the vertices of `triangles`; writes each triangle's cluster (offset by `first_id`)
// into cluster_of and returns how many ids it used.
std::uint32_t kmeans_triangles(const mesh_data& mesh, std::span<const std::uint32_t> triangles, std::uint32_t k,
                               std::uint64_t seed, std::uint32_t max_iterations, std::uint32_t first_id,
                               std::vector<std::uint32_t>& cluster_of) {
    if (triangles.empty()) return 0;
    const std::vector<std::uint32_t> vertices = triangle_vertices(mesh, triangles);
    std::vector<glm::vec3> points(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) points[i] = mesh.vertices[vertices[i]].position;
    std::vector<std::uint32_t> labels = kmeans(points, std::max<std::uint32_t>(k, 1), seed, max_iterations);
    auto label_of = [&](std::uint32_t vertex) {
        return labels[std::size_t(std::lower_bound(vertices.begin(), vertices.end(), vertex) - vertices.begin())];
    };
    std::vector<std::uint32_t> triangle_labels(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const std::uint32_t* index = &mesh.indices[std::size_t(triangles[i]) * 3];
        triangle_labels[i] = vote(label_of(index[0]), label_of(index[1]), label_of(index[2]));
    }
    const std::uint32_t used = compact(triangle_labels);  // a cluster may have lost every triangle
    for (std::size_t i = 0; i < triangles.size(); ++i) cluster_of[triangles[i]] = first_id + triangle_labels[i];
    return used;
}

double triangle_area(const mesh_data& mesh, std::uint32_t t) {
    const std::uint32_t* i = &mesh.indices[std::size_t(t) * 3];
    const glm::vec3 a = mesh.vertices[i[0]].position;
    return 0.5 * double(glm::length(glm::cross(mesh.vertices[i[1]].position - a, mesh.vertices[i[2]].position - a)));
}

// ---- hierarchy -------------------------------------------------------------------------------

// The stems named by mesh.parts, each with its parent and depth in the parent links.
class stem_tree {
public:
    explicit stem_tree(const std::vector<triangle_part>& parts) {
        // Bark states its stem's parent first-hand; foliage does too (mesh.h), and is the only
        // source for stems without bark.
        for (const bool bark : {true, false})
            for (const triangle_part& p : parts)
                if ((p.kind == part_kind::bark) == bark) m_parent.emplace(p.branch, p.parent_branch);
        for (const auto& [stem, parent] : m_parent) m_depth[stem] = depth_of(stem);
    }

    int max_depth() const {
        int deepest = 0;
        for (const auto& [stem, depth] : m_depth) deepest = std::max(deepest, depth);
        return deepest;
    }

    // The stem's ancestor at `level` (the stem itself when it is at or above that level).
    std::uint32_t anchor(std::uint32_t stem, int level) const {
        for (int depth = m_depth.at(stem); depth > level; --depth) stem = m_parent.at(stem);
        return stem;
    }

private:
    // Roots name themselves or a stem no triangle names; a cycle (a malformed import) is cut
    // where it closes.
    int depth_of(std::uint32_t stem) const {
        int depth = 0;
        for (std::size_t steps = 0; steps <= m_parent.size(); ++steps) {
            const auto it = m_parent.find(stem);
            if (it == m_parent.end() || it->second == stem || !m_parent.count(it->second)) return depth;
            stem = it->second;
            ++depth;
        }
        return 0;
    }

    std::map<std::uint32_t, std::uint32_t> m_parent;
    std::map<std::uint32_t, int> m_depth;
};

// Cluster of every triangle at one branching level: (anchor stem, foliage or bark).
std::vector<std::uint32_t> clusters_at_level(const mesh_data& mesh, const std::vector<triangle_kind>& kinds,
                                             const stem_tree& stems, int level, std::uint32_t& count) {
    std::vector<std::uint32_t> cluster_of(kinds.size(), k_no_cluster);
    std::map<std::pair<std::uint32_t, bool>, std::uint32_t> ids;
    for (std::size_t t = 0; t < kinds.size(); ++t) {
        if (kinds[t] == triangle_kind::none) continue;
        const std::pair key{stems.anchor(mesh.parts[t].branch, level), kinds[t] == triangle_kind::foliage};
        cluster_of[t] = ids.emplace(key, std::uint32_t(ids.size())).first->second;
    }
    count = std::uint32_t(ids.size());
    return cluster_of;
}

// Fewer clusters than half the target: each is split by k-means on its own vertices, into a
// share of the target proportional to its triangles (at least one).
std::uint32_t split_clusters(const mesh_data& mesh, const clustering_settings& s, std::uint32_t count,
                             std::vector<std::uint32_t>& cluster_of) {
    std::vector<std::vector<std::uint32_t>> members(count);
    std::size_t total = 0;
    for (std::uint32_t t = 0; t < cluster_of.size(); ++t)
        if (cluster_of[t] != k_no_cluster) members[cluster_of[t]].push_back(t), ++total;
    std::uint32_t next = 0;
    for (std::uint32_t c = 0; c < count; ++c) {
        const double share = double(members[c].size()) / double(total);
        const auto k = std::max<std::uint32_t>(1, std::uint32_t(std::lround(share * double(s.target_clusters))));
        next += kmeans_triangles(mesh, members[c], k, hash_combine(s.seed, c), s.max_iterations, next, cluster_of);
    }
    return next;
}

// More than twice the target: whole clusters (sub-branches) are merged by k-means on their
// centroids, foliage and bark apart, each kind keeping its share of the target.
std::uint32_t merge_clusters(const mesh_data& mesh, const std::vector<triangle_kind>& kinds,
                             const clustering_settings& s, std::uint32_t count, std::vector<std::uint32_t>& cluster_of) {
    std::vector<glm::dvec3> sum(count, glm::dvec3(0.0));
    std::vector<std::size_t> corners(count, 0);
    std::vector<bool> foliage(count, false);
    for (std::size_t t = 0; t < cluster_of.size(); ++t) {
        const std::uint32_t c = cluster_of[t];
        if (c == k_no_cluster) continue;
        foliage[c] = kinds[t] == triangle_kind::foliage;
        for (int k = 0; k < 3; ++k) sum[c] += glm::dvec3(mesh.vertices[mesh.indices[t * 3 + std::size_t(k)]].position);
        corners[c] += 3;
    }
    std::vector<std::uint32_t> merged(count);
    std::uint32_t next = 0;
    for (const bool leaves : {false, true}) {
        std::vector<std::uint32_t> ids;
        std::vector<glm::vec3> centroids;
        for (std::uint32_t c = 0; c < count; ++c)
            if (foliage[c] == leaves) ids.push_back(c), centroids.emplace_back(sum[c] / double(corners[c]));
        if (ids.empty()) continue;
        const auto k = std::max<std::uint32_t>(
            1, std::uint32_t(std::lround(double(s.target_clusters) * double(ids.size()) / double(count))));
        std::vector<std::uint32_t> labels = kmeans(centroids, k, hash_combine(s.seed, leaves), s.max_iterations);
        std::uint32_t used = 0;
        for (std::size_t i = 0; i < ids.size(); ++i) {
            merged[ids[i]] = next + labels[i];
            used = std::max(used, labels[i] + 1);
        }
        next += used;
    }
    for (std::uint32_t& c : cluster_of)
        if (c != k_no_cluster) c = merged[c];
    return next;
}

triangle_clusters hierarchy_clusters(const mesh_data& mesh, const std::vector<triangle_kind>& kinds,
                                     const clustering_settings& s) {
    const stem_tree stems(mesh.parts);
    triangle_clusters out;
    out.method = clustering_method::hierarchy;
    if (s.branching_level >= 0) {
        out.branching_level = s.branching_level;
        out.cluster_of = clusters_at_level(mesh, kinds, stems, s.branching_level, out.count);
        return out;
    }
    // The level whose count is nearest the target by ratio; ties to the shallower level.
    double best = std::numeric_limits<double>::infinity();
    for (int level = 0; level <= stems.max_depth(); ++level) {
        std::uint32_t count = 0;
        std::vector<std::uint32_t> cluster_of = clusters_at_level(mesh, kinds, stems, level, count);
        const double off = std::abs(std::log(double(std::max<std::uint32_t>(count, 1)) / double(s.target_clusters)));
        if (off < best) {
            best = off;
            out.branching_level = level;
            out.count = count;
            out.cluster_of = std::move(cluster_of);
        }
    }
    if (out.count > 2 * std::uint64_t(s.target_clusters))
        out.count = merge_clusters(mesh, kinds, s, out.count, out.cluster_of);
    else if (2 * std::uint64_t(out.count) < s.target_clusters)
        out.count = split_clusters(mesh, s, out.count, out.cluster_of);
    out.count = compact(out.cluster_of);
    return out;
}

triangle_clusters kmeans_clusters(const mesh_data& mesh, const std::vector<triangle_kind>& kinds,
                                  const clustering_settings& s, bool keep_kinds_apart) {
    triangle_clusters out;
    out.method = keep_kinds_apart ? clustering_method::geometric : clustering_method::kmeans;
    out.cluster_of.assign(kinds.size(), k_no_cluster);
    std::vector<std::uint32_t> bark, foliage, all;
    double bark_area = 0.0, foliage_area = 0.0;
    for (std::uint32_t t = 0; t < kinds.size(); ++t) {
        if (kinds[t] == triangle_kind::none) continue;
        all.push_back(t);
        (kinds[t] == triangle_kind::bark ? bark : foliage).push_back(t);
        (kinds[t] == triangle_kind::bark ? bark_area : foliage_area) += triangle_area(mesh, t);
    }
    if (!keep_kinds_apart) {
        out.count = kmeans_triangles(mesh, all, s.target_clusters, s.seed, s.max_iterations, 0, out.cluster_of);
        return out;
    }
    const double total = bark_area + foliage_area;
    const auto bark_k = std::uint32_t(std::lround(total > 0.0 ? double(s.target_clusters) * bark_area / total : 0.0));
    const std::uint32_t k_bark = bark.empty() ? 0 : std::clamp<std::uint32_t>(bark_k, 1, s.target_clusters);
    const std::uint32_t k_foliage = foliage.empty() ? 0 : std::max<std::uint32_t>(1, s.target_clusters - std::min(k_bark, s.target_clusters - 1));
    out.count = kmeans_triangles(mesh, bark, k_bark, hash_combine(s.seed, 0), s.max_iterations, 0, out.cluster_of);
    out.count += kmeans_triangles(mesh, foliage, k_foliage, hash_combine(s.seed, 1), s.max_iterations, out.count,
                                  out.cluster_of);
    out.count = compact(out.cluster_of);
    return out;
}

}  // namespace

std::string_view name_of(clustering_method method) {
    switch (method) {
        case clustering_method::automatic: return "automatic";
        case clustering_method::kmeans: return "kmeans";
        case clustering_method::hierarchy: return "hierarchy";
        case clustering_method::geometric: return "geometric";
    }
    return "unknown";
}

std::vector<std::vector<std::uint32_t>> triangle_clusters::triangles() const {
    std::vector<std::vector<std::uint32_t>> out(count);
    for (std::uint32_t t = 0; t < cluster_of.size(); ++t)
        if (cluster_of[t] != k_no_cluster) out[cluster_of[t]].push_back(t);
    return out;
}

std::vector<std::uint32_t> kmeans(std::span<const glm::vec3> points, std::uint32_t k, std::uint64_t seed,
                                  std::uint32_t max_iterations) {
    if (points.empty()) return {};
    if (k == 0) throw std::invalid_argument("kmeans: k must be at least 1 for " + std::to_string(points.size()) + " points");
    rng random(seed);
    std::vector<glm::dvec3> centres = seed_centres(points, std::min<std::uint32_t>(k, std::uint32_t(points.size())), random);
    std::vector<std::uint32_t> labels(points.size(), k_no_cluster);
    for (std::uint32_t iteration = 0; iteration < std::max<std::uint32_t>(max_iterations, 1); ++iteration) {
        if (!assign(points, centres, labels)) break;  // the first pass always changes every label
        std::vector<glm::dvec3> sum(centres.size(), glm::dvec3(0.0));
        std::vector<std::size_t> members(centres.size(), 0);
        for (std::size_t i = 0; i < points.size(); ++i) sum[labels[i]] += glm::dvec3(points[i]), ++members[labels[i]];
        for (std::size_t c = 0; c < centres.size(); ++c)
            if (members[c]) centres[c] = sum[c] / double(members[c]);  // an empty centre stays put
    }
    compact(labels);
    return labels;
}

triangle_clusters cluster_triangles(const mesh_data& mesh, bool has_hierarchy, const clustering_settings& settings) {
    if (settings.target_clusters == 0) throw std::invalid_argument("cluster_triangles: target_clusters must be at least 1");
    if (settings.branching_level < -1)
        throw std::invalid_argument("cluster_triangles: branching_level must be -1 (steered) or >= 0, got " +
                                    std::to_string(settings.branching_level));
    const bool hierarchy_known = has_hierarchy && mesh.parts.size() == mesh.triangle_count();
    clustering_method method = settings.method;
    if (method == clustering_method::automatic)
        method = hierarchy_known ? clustering_method::hierarchy : clustering_method::geometric;
    if (method == clustering_method::hierarchy && !hierarchy_known)
        throw std::invalid_argument("cluster_triangles: hierarchy clustering asked for, but the mesh has no branch "
                                    "hierarchy (" + std::to_string(mesh.parts.size()) + " parts for " +
                                    std::to_string(mesh.triangle_count()) + " triangles); use kmeans or geometric");
    const std::vector<triangle_kind> kinds = kinds_of(mesh);
    switch (method) {
        case clustering_method::hierarchy: return hierarchy_clusters(mesh, kinds, settings);
        case clustering_method::geometric: return kmeans_clusters(mesh, kinds, settings, true);
        default: return kmeans_clusters(mesh, kinds, settings, false);
    }
}

}  // namespace sylva
