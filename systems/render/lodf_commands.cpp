#include "systems/render/lodf_commands.h"

#include <stdexcept>

#include "lod/lodf.h"

namespace sylva::render {

lodf_commands::lodf_commands(std::uint32_t slots, std::uint32_t clusters_per_slot)
    : m_per_slot(clusters_per_slot),
      m_slots(slots),
      m_mirror(std::size_t(slots) * clusters_per_slot),
      m_buffer(make_buffer()) {
    glNamedBufferStorage(m_buffer.id(), GLsizeiptr(std::max<std::size_t>(m_mirror.size(), 1) * sizeof(command)),
                         m_mirror.data(), GL_DYNAMIC_STORAGE_BIT);
}

lodf_commands::command lodf_commands::command_of(const slot_state& s, std::uint32_t cluster, const cluster_changes& c,
                                                 std::int32_t base_vertex, std::uint32_t base_instance) const {
    const lodf_range r = active_range(*s.lodf, cluster, c);
    return {r.index_count, r.index_count ? 1u : 0u, s.first_index + r.first_index, base_vertex, base_instance};
}

std::uint64_t lodf_commands::upload(std::uint32_t slot, std::uint32_t first, std::uint32_t count) {
    const std::size_t at = std::size_t(slot) * m_per_slot + first;
    const auto bytes = GLsizeiptr(std::size_t(count) * sizeof(command));
    glNamedBufferSubData(m_buffer.id(), GLintptr(at * sizeof(command)), bytes, &m_mirror[at]);
    m_uploaded += std::uint64_t(bytes);
    return std::uint64_t(bytes);
}

std::uint64_t lodf_commands::assign(std::uint32_t slot, const lodf_structure& lodf, const gpu_submesh& foliage,
                                    std::uint32_t base_instance, std::span<const cluster_changes> clusters) {
    if (slot >= m_slots.size()) throw std::out_of_range("lodf_commands: no slot " + std::to_string(slot));
    const auto n = std::uint32_t(lodf.clusters.size());
    if (n > m_per_slot || clusters.size() != n)
        throw std::logic_error("lodf_commands: " + std::to_string(n) + " clusters for a slot of " + std::to_string(m_per_slot));
    slot_state& s = m_slots[slot];
    s = {&lodf, n, foliage.first_index};
    command* out = &m_mirror[std::size_t(slot) * m_per_slot];
    for (std::uint32_t c = 0; c < m_per_slot; ++c)
        out[c] = c < n ? command_of(s, c, clusters[c], foliage.base_vertex, base_instance) : command{};
    return upload(slot, 0, m_per_slot);
}

std::uint64_t lodf_commands::update(std::uint32_t slot, std::span<const cluster_changes> clusters) {
    const slot_state& s = m_slots.at(slot);
    if (!s.lodf || clusters.size() != s.clusters) return 0;
    command* mirror = &m_mirror[std::size_t(slot) * m_per_slot];
    std::uint64_t bytes = 0;
    std::uint32_t run_start = 0, run = 0;
    for (std::uint32_t c = 0; c <= s.clusters; ++c) {
        bool changed = false;
        if (c < s.clusters) {
            const command now = command_of(s, c, clusters[c], mirror[c].base_vertex, mirror[c].base_instance);
            changed = !(now == mirror[c]);
            if (changed) mirror[c] = now;
        }
        if (changed) {
            if (run == 0) run_start = c;
            ++run;
        } else if (run > 0) {
            bytes += upload(slot, run_start, run);
            run = 0;
        }
    }
    return bytes;
}

std::uint64_t lodf_commands::release(std::uint32_t slot) {
    slot_state& s = m_slots.at(slot);
    s = {};
    command* mirror = &m_mirror[std::size_t(slot) * m_per_slot];
    for (std::uint32_t c = 0; c < m_per_slot; ++c) mirror[c] = {};
    return upload(slot, 0, m_per_slot);
}

std::span<const lodf_commands::command> lodf_commands::slot_mirror(std::uint32_t slot) const {
    return {&m_mirror[std::size_t(slot) * m_per_slot], m_per_slot};
}

}  // namespace sylva::render
