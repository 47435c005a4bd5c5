#include "ecs/world.h"

#include <algorithm>
#include <mutex>

namespace sylva::ecs {

// Remembers which (driver, other) table pairs were found aligned at which layout versions, so a
// query built every frame over unchanged tables costs a lookup, not an O(n) comparison. The mutex
// is there because systems of one phase build queries concurrently.
struct world::alignment_cache {
    struct record {
        const table_base* driver;
        const table_base* other;
        std::uint64_t driver_version;
        std::uint64_t other_version;
        bool aligned;
    };
    std::mutex mutex;
    std::vector<record> records;
};

world::world() : m_alignment(std::make_unique<alignment_cache>()) {}
world::~world() = default;
world::world(world&&) noexcept = default;
world& world::operator=(world&&) noexcept = default;

entity world::create() {
    ++m_alive_count;
    if (!m_free.empty()) {
        const std::uint32_t index = m_free.back();
        m_free.pop_back();
        m_slots[index].alive = true;
        return {index, m_slots[index].generation};
    }
    if (m_slots.size() >= k_null_index)
        throw std::length_error("ecs::world::create: entity indices exhausted");
    m_slots.push_back({0, true});
    return {static_cast<std::uint32_t>(m_slots.size() - 1), 0};
}

void world::destroy(entity e) {
    if (!alive(e)) return;
    for (const auto& t : m_tables)
        if (t) t->remove(e);
    slot& s = m_slots[e.index];
    s.alive = false;
    ++s.generation;  // every handle to the old occupant is now stale
    m_free.push_back(e.index);
    --m_alive_count;
}

bool world::alive(entity e) const {
    return e.index < m_slots.size() && m_slots[e.index].alive &&
           m_slots[e.index].generation == e.generation;
}

void world::require_alive(entity e, const char* operation) const {
    if (!alive(e))
        throw std::logic_error(std::string("ecs::world::") + operation +
                               ": entity is dead or stale");
}

void world::set_chunk_size(std::size_t chunk) {
    if (chunk == 0)
        throw std::invalid_argument("ecs::world::set_chunk_size: chunk must be positive, got 0");
    m_chunk_size = chunk;
}

std::size_t world::checked_single_index(std::size_t size, const char* type_name) {
    if (size != 1)
        throw std::logic_error("ecs::world::single: expected exactly one entity with " +
                               std::string(type_name) + ", found " + std::to_string(size));
    return 0;
}

bool world::tables_aligned(const table_base& driver, const table_base& other) const {
    const std::lock_guard lock(m_alignment->mutex);
    auto& records = m_alignment->records;
    auto it = std::find_if(records.begin(), records.end(), [&](const alignment_cache::record& r) {
        return r.driver == &driver && r.other == &other;
    });
    if (it != records.end() && it->driver_version == driver.layout_version() &&
        it->other_version == other.layout_version())
        return it->aligned;

    const std::span<const entity> lead = driver.entities();
    const std::span<const entity> follow = other.entities();
    const bool aligned =
        follow.size() >= lead.size() && std::equal(lead.begin(), lead.end(), follow.begin());
    const alignment_cache::record fresh{&driver, &other, driver.layout_version(),
                                        other.layout_version(), aligned};
    if (it != records.end())
        *it = fresh;
    else
        records.push_back(fresh);
    return aligned;
}

}  // namespace sylva::ecs
