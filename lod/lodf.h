#pragma once
// LoDF's retrieval algorithms (Rebollo 2006 §3.3): moving a plant's foliage between levels of
// detail by walking Changed_group and updating only the clusters it names. The structure they
// walk, and why each cluster's active leaves are one contiguous run, is
// models/bake/lodf_structure.h.
#include <cstdint>
#include <span>
#include <vector>

#include "components/cluster_changes.h"
#include "models/bake/lodf_bake.h"
#include "models/bake/lodf_structure.h"
#include "models/mesh.h"

namespace sylva {

// Every cluster at F_0: init_group 0, active_leaves L_c, changes_number 0 (Figure 7).
void reset_lodf_clusters(const lodf_structure& lodf, std::span<cluster_changes> clusters);

// §3.3, first half: walks Changed_group from `from` collapses to `to`, adding one to the
// changes_number of the cluster of every collapse (from < to) or split (from > to) on the way.
void count_lodf_changes(const lodf_structure& lodf, std::span<cluster_changes> clusters, std::uint32_t from,
                        std::uint32_t to);
// §3.3, second half: every cluster whose changes_number is not 0 is updated by Eq. 10 and 11
// when reducing detail (init_group += 2·changes, active_leaves −= changes) or Eq. 12 and 13 when
// increasing it, and its count reset to 0. Those clusters are appended to `changed` in increasing
// order (cleared first; reserve G to stay allocation-free); returns their number.
std::uint32_t apply_lodf_changes(std::span<cluster_changes> clusters, bool reduce, std::vector<std::uint32_t>& changed);
// Both: moves a plant from `init_position` collapses to `target` (clamped to the sequence).
std::uint32_t retarget_lodf(const lodf_structure& lodf, std::span<cluster_changes> clusters,
                            std::uint32_t& init_position, std::uint32_t target,
                            std::vector<std::uint32_t>& changed);

// glMultiDrawElementsIndirect's command (GL 4.3 §10.4): what a cluster's draw is, and what LoDF
// uploads per changed cluster (systems/render/lodf_commands.h).
struct lodf_draw_command {
    std::uint32_t count = 0;
    std::uint32_t instance_count = 0;
    std::uint32_t first_index = 0;
    std::int32_t base_vertex = 0;
    std::uint32_t base_instance = 0;
    bool operator==(const lodf_draw_command&) const = default;
};
static_assert(sizeof(lodf_draw_command) == 20);

// The index range a cluster draws: its active leaves' triangles.
struct lodf_range {
    std::uint32_t first_index = 0;
    std::uint32_t index_count = 0;
};
lodf_range active_range(const lodf_structure& lodf, std::uint32_t cluster, const cluster_changes& state);

// The leaf numbers of a cluster's active run, in array order (tests, inspect, export).
std::vector<std::uint32_t> active_leaves_of(const lodf_structure& lodf, std::uint32_t cluster,
                                            const cluster_changes& state);

// Collapses that leave `leaves` leaves drawn, clamped to [G, L].
std::uint32_t collapses_for_leaves(const lodf_structure& lodf, std::uint32_t leaves);

// The plant's full mesh with its foliage at `leaves` leaves (clamped to [G, L]): the same
// vertices (Eq. 3), every other submesh as it is, then one leaf submesh of the clusters' active
// runs. Per-triangle parts and leaf records are dropped (they describe F_0's triangles).
mesh_data lodf_mesh(const mesh_data& full, const lodf_model& model, std::uint32_t leaves);

}  // namespace sylva
