#pragma once
// The LoDF bake (Rebollo 2006 §3.1, on a leaf-collapse sequence in the spirit of FSA, Remolar et
// al. 2002): a plant's foliage as the multiresolution structure of lod/lodf.h, plus the index
// list every leaf of it is drawn with. Eq. 3, |V^r| = V: every leaf a collapse makes is a quad
// on four vertices of the leaves it replaces, so the plant's full mesh's vertices serve every
// level and nothing is added to them.
//
// Leaves (§3): the connected pieces of the foliage triangles (material leaf): a generated card,
// or an imported model's leaf primitive split where its triangles share no vertex.
// Clusters: the leaves in the order of the plant's branch hierarchy when it has one (a stem's
// leaves, then those of the stems it carries, depth first), else along a Morton curve through
// their centres, cut into G runs of equal length: a cluster is a few neighbouring twigs, so its
// collapses stay on one part of the crown and a change of detail there touches one cluster.
// Collapses (models/bake/lodf_bake.cpp): each cluster's tree is built round by round, every
// round pairing its leaves by the least collapse cost among nanoflann neighbours, in the queue
// shape lod/lodf.h needs; the clusters' collapses are then merged into one Changed_group by cost,
// cheapest first.
#include <cstdint>
#include <vector>

#include "models/bake/lodf_structure.h"
#include "models/mesh.h"

namespace sylva {

// Leaves per cluster when lodf_settings::clusters is 0: G = ⌈L / this⌉. A cluster's change is
// one 20-byte draw command whatever its size; smaller clusters make more commands per plant,
// larger ones make a change touch more leaves than it needs to (none of it is uploaded).
inline constexpr std::uint32_t k_lodf_leaves_per_cluster = 256;
// Neighbours each leaf considers as its collapse partner in a round (nanoflann k-NN).
inline constexpr std::uint32_t k_lodf_neighbours = 8;

struct lodf_settings {
    std::uint32_t clusters = 0;  // G; 0: ⌈L / leaves_per_cluster⌉
    std::uint32_t leaves_per_cluster = k_lodf_leaves_per_cluster;
};

struct lodf_model {
    lodf_structure structure;  // node index ranges point into `indices`
    // Every leaf of F^r's triangles, cluster by cluster in array order: an original leaf's own
    // triangles, a made leaf's two (a quad on four existing vertices).
    std::vector<std::uint32_t> indices;
    std::uint32_t vertex_count = 0;  // of the full mesh the indices address (Eq. 3: |V^r| = V)
    std::uint32_t crown_vertices = 0;  // the paper's V: those of the foliage (Eq. 4: L = V / 4 for cards)
    // How well the made leaves keep the area of the pairs they replace: the made quad's area over
    // the sum of its two leaves' areas, mean over all collapses (1 is exact).
    float mean_area_ratio = 1.0f;
};

// Bakes `full` (a plant's full-detail mesh). A mesh without foliage gives an empty model
// (leaf_count 0). Deterministic: the same mesh and settings give the same bytes.
lodf_model bake_lodf(const mesh_data& full, bool has_hierarchy, const lodf_settings& settings = {});

// The collapse cost of two leaves of areas a, b, centres ca, cb and unit normals na, nb, made into
// a quad of area q (models/bake/lodf_leaves.h collapse_quad): the area that moves times how far
// it moves (each leaf's area carried to the pair's area-weighted centre, 2ab/(a+b)·|ca − cb| in
// all), plus the pair's area turned by the angle between their faces (the rim of the new leaf,
// of side √(a+b), sweeping 1 − |na·nb| of it), plus the area the quad gains or loses against the
// pair's, times that side: FSA's new leaf keeps "an area similar to that of the collapsed leaves"
// (Remolar 2002), and on Eq. 3's existing vertices only some pairs can. In m³: small for small,
// close, parallel leaves that lie side by side, so the crown's fine detail goes first and its
// coverage and outline last.
float lodf_collapse_cost(float a, const glm::vec3& ca, const glm::vec3& na, float b, const glm::vec3& cb,
                         const glm::vec3& nb, float q);

// The storage of the structure in the words of the paper's Eq. 7–8 (3 per crown vertex, 6 per
// leaf of F^r, 3 per cluster, 1 per Changed_group entry), and Eq. 9's estimate 6.25·V for the
// same crown vertices V.
struct lodf_storage {
    std::uint64_t words = 0;
    double eq9_words = 0.0;
    std::uint64_t bytes = 0;  // what this implementation stores: nodes, indices, clusters, sequence
};
lodf_storage lodf_storage_of(const lodf_model& model);

}  // namespace sylva
