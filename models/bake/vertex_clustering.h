#pragma once
// Behrendt 2005 §2.1: the clusters of a plant's geometry that billboard clouds
// (models/bake/billboard_cloud.h) turn into billboards, one cluster's triangles per set of billboards.
//
//   kmeans     the paper's baseline: plain k-means on the model's vertices, leaf and bark alike
//              ("a suboptimal set of billboards ... especially for the trunk and the skeleton").
//   hierarchy  the paper's better clustering: every sub-branch at a chosen branching level is one
//              cluster, with the foliage of the stem that carries it, leaves and bark apart.
//   geometric  for imported models without a hierarchy: k-means on leaf and on bark vertices
//              separately, so no cluster mixes the trunk with the foliage around it.
//
// Leaves and bark are told apart by each triangle's sub-mesh material. For generated plants the
// generator knows; for glTF imports the importer decided it from the texture's alpha ratio and
// colour (models/gltf/gltf_plant_builder.cpp), which is the paper's criterion ("the color and the
// ratio of transparent and opaque texels on the triangles").
//
// Deterministic: seeded with models/random.h, k-means++ initialisation, a fixed iteration cap,
// every sum taken in point order; the parallel assignment step writes one label per point, so
// the result does not depend on the thread count.
#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "models/mesh.h"

namespace sylva {

enum class clustering_method : std::uint8_t {
    automatic,  // hierarchy when the model has one (plant_model::has_hierarchy), else geometric
    kmeans,
    hierarchy,
    geometric,
};
std::string_view name_of(clustering_method method);

struct clustering_settings {
    clustering_method method = clustering_method::automatic;
    // The rough number of clusters (the paper lets the user choose it: 50-200 billboards for
    // trees, 20-100 for small plants, each cluster giving one to three).
    std::uint32_t target_clusters = 60;
    // hierarchy: the branching level whose sub-branches are the clusters (0: the trunk and each
    // ground stem with everything on it). -1 steers it by target_clusters; see cluster_triangles.
    int branching_level = -1;
    std::uint64_t seed = 1;
    std::uint32_t max_iterations = 30;  // k-means: Lloyd iterations at most
};

inline constexpr std::uint32_t k_no_cluster = std::numeric_limits<std::uint32_t>::max();

struct triangle_clusters {
    clustering_method method = clustering_method::kmeans;  // what was used, never automatic
    int branching_level = -1;  // hierarchy: the level used; -1 otherwise
    std::uint32_t count = 0;
    // Per triangle of the mesh: its cluster in 0..count-1, numbered in order of first appearance,
    // or k_no_cluster for a triangle in no sub-mesh (never drawn).
    std::vector<std::uint32_t> cluster_of;

    // Each cluster's triangles, ascending.
    std::vector<std::vector<std::uint32_t>> triangles() const;
};

// The vertices `triangles` use (indices into mesh.vertices), sorted, each once.
std::vector<std::uint32_t> triangle_vertices(const mesh_data& mesh, std::span<const std::uint32_t> triangles);

// Plain k-means (Lloyd's iterations after k-means++ seeding) on points: a label in 0..k'-1 per
// point, numbered in order of first appearance, k' <= k (fewer when there are fewer distinct
// points). Ties go to the lower centre. Throws std::invalid_argument for k = 0 with points.
std::vector<std::uint32_t> kmeans(std::span<const glm::vec3> points, std::uint32_t k, std::uint64_t seed,
                                  std::uint32_t max_iterations);

// Clusters every triangle in a sub-mesh. `has_hierarchy` is plant_model::has_hierarchy; the
// hierarchy also needs one triangle_part per triangle.
//
// hierarchy: stems are the `branch` ids of mesh.parts, linked by parent_branch; a stem's level is
// its depth in those links (so imports, whose nodes are the stems, work too). Every triangle goes
// to the ancestor of its stem at the branching level (its own stem when that is shallower), and
// foliage and bark of that ancestor are separate clusters. With branching_level -1 the level
// whose count is nearest target_clusters (by ratio) is used; then, if that count is still more
// than twice the target, whole sub-branches are merged by k-means on their centroids (foliage and
// bark apart), and if it is less than half (small plants have shallow hierarchies), each cluster
// is split by k-means on its own vertices, so a cluster never straddles two sub-branches.
//
// kmeans and geometric: a triangle goes to the cluster holding most of its three vertices (its
// first vertex's when all three differ). geometric shares the target between foliage and bark in
// proportion to their surface area, at least one cluster each.
//
// Throws std::invalid_argument naming the problem: target 0, hierarchy asked for a mesh without
// one, a branching level below -1.
triangle_clusters cluster_triangles(const mesh_data& mesh, bool has_hierarchy, const clustering_settings& settings);

}  // namespace sylva
