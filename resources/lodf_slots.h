#pragma once
// The plants on the LoDF rung (Rebollo 2006) this frame, each in a slot: a fixed range of
// foliage-cluster entities (components/cluster_changes.h, one per cluster, created at spawn) and
// a fixed range of indirect commands on the GPU (systems/render/lodf_commands.h), so a plant
// keeps its clusters' state and commands while it stays on the rung and a change of its detail
// rewrites only what changed. Writer: update_lodf (systems/update_lodf_system.h); read by
// build_draw_list (which draws a plant without a slot as mesh_full) and the renderer.
#include <cstdint>
#include <limits>
#include <vector>

namespace sylva {

// Plants on the LoDF rung at once: a scenario's lod.lodf_slots (32 unless it says). Each holds
// clusters_per_slot cluster entities and as many 20-byte commands: 32 slots of broadleaf_hd's
// 120 clusters are 3,840 entities and 77 KB of commands. A plant beyond them is drawn as
// mesh_full (the same plant at full detail) and counted in `overflow`; the rung is for the
// nearest plants, which a ladder keeps few.
inline constexpr std::uint32_t k_no_lodf_slot = std::numeric_limits<std::uint32_t>::max();

struct lodf_slot {
    std::uint32_t plant = k_no_lodf_slot;  // dense plant index; k_no_lodf_slot when free
    std::uint32_t species = 0;
    std::uint32_t init_position = 0;  // Changed_group's init_position: collapses made
    std::uint32_t leaves = 0;         // drawn this frame
    // 1 in the frame the slot took its plant: its commands are written whole, not updated.
    std::uint8_t taken = 0;
};

struct lodf_slots {
    std::vector<lodf_slot> slots;            // lod.lodf_slots when a ladder reaches lodf, else none
    std::uint32_t clusters_per_slot = 0;     // the most clusters of any species
    std::vector<std::uint32_t> slot_of_plant;  // by dense plant index
    std::uint32_t overflow = 0;              // plants on the rung this frame without a slot
    std::uint32_t changed_clusters = 0;      // this frame, over every slot
    // Per slot, the clusters whose counters changed this frame (reserved for clusters_per_slot:
    // the frame loop does not allocate).
    std::vector<std::vector<std::uint32_t>> changed;
};

}  // namespace sylva
