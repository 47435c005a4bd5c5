#pragma once
// The GPU side of LoDF's clusters (Rebollo 2006 §4, "only the information of the changed
// clusters are updated and sent to the graphics system"): one glMultiDrawElementsIndirect
// command (GL 4.3 §10.4) per cluster per plant slot, kept in one persistent buffer over each
// species' static foliage index list (mesh_pool::add_indices). A cluster's active leaves are one
// contiguous index range (models/bake/lodf_structure.h), so a change of detail rewrites the
// commands of the clusters whose counters changed, 20 bytes each, and uploads only those bytes;
// the foliage's indices and vertices never move.
#include <cstdint>
#include <span>
#include <vector>

#include "components/cluster_changes.h"
#include "lod/lodf.h"
#include "models/bake/lodf_structure.h"
#include "systems/render/gl_objects.h"
#include "systems/render/mesh_pool.h"

namespace sylva::render {

class lodf_commands {
public:
    // Room for `slots` plants of at most `clusters_per_slot` clusters each; every command starts
    // drawing nothing.
    lodf_commands(std::uint32_t slots, std::uint32_t clusters_per_slot);

    // Points `slot` at a species' foliage (`lodf`, uploaded as `foliage`) drawn for instance
    // `base_instance`, its clusters at `clusters`: writes and uploads all the slot's commands.
    // Returns the bytes uploaded.
    std::uint64_t assign(std::uint32_t slot, const lodf_structure& lodf, const gpu_submesh& foliage,
                         std::uint32_t base_instance, std::span<const cluster_changes> clusters);
    // Rewrites the commands of the slot's clusters whose active range differs from what their
    // command draws, uploading each run of consecutive changed commands with one
    // glNamedBufferSubData. Returns the bytes uploaded (0 when nothing changed).
    std::uint64_t update(std::uint32_t slot, std::span<const cluster_changes> clusters);
    // The slot draws nothing until assigned again.
    std::uint64_t release(std::uint32_t slot);

    GLuint buffer() const { return m_buffer.id(); }
    // Byte offset of a slot's first command, and its command count (its species' clusters).
    std::size_t slot_offset(std::uint32_t slot) const { return std::size_t(slot) * m_per_slot * sizeof(command); }
    std::uint32_t slot_commands(std::uint32_t slot) const { return m_slots[slot].clusters; }
    std::uint64_t uploaded_bytes() const { return m_uploaded; }

    using command = lodf_draw_command;  // lod/lodf.h
    // What the CPU holds for the slot (tests compare it with the buffer).
    std::span<const command> slot_mirror(std::uint32_t slot) const;

private:
    struct slot_state {
        const lodf_structure* lodf = nullptr;
        std::uint32_t clusters = 0;
        std::uint32_t first_index = 0;  // of the species' foliage index list in the pool
    };
    command command_of(const slot_state& s, std::uint32_t cluster, const cluster_changes& c,
                       std::int32_t base_vertex, std::uint32_t base_instance) const;
    std::uint64_t upload(std::uint32_t slot, std::uint32_t first, std::uint32_t count);

    std::uint32_t m_per_slot;
    std::vector<slot_state> m_slots;
    std::vector<command> m_mirror;  // slots × m_per_slot
    gl_buffer m_buffer;
    std::uint64_t m_uploaded = 0;
};

}  // namespace sylva::render
