#pragma once
// The world owns entities, one component_table per component type, and resources (singletons
// that belong to no entity: species library, draw lists, frame stats). Hand-written rather than
// taken from EnTT/flecs because the design asks us to own the ECS (DESIGN.md §2): its scheduler
// contract, determinism rules and table layout are ours to reason about.
//
// Thread safety: during a phase, systems may call any const member and mutate component values
// and resources concurrently as their declarations allow. Structural changes (create, destroy,
// emplace of a new component, remove, align, set_resource, first use of a table) happen only
// between phases — the scheduler guarantees that and pre-creates every declared table.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <typeinfo>
#include <utility>
#include <vector>

#include "ecs/component_table.h"
#include "ecs/entity.h"
#include "ecs/parallel.h"
#include "ecs/query.h"
#include "ecs/type_id.h"
#include "ecs/type_list.h"

namespace sylva::ecs {

class world {
public:
    world();
    ~world();
    world(world&&) noexcept;
    world& operator=(world&&) noexcept;
    world(const world&) = delete;
    world& operator=(const world&) = delete;

    // --- entities
    entity create();
    void destroy(entity e);  // strips every component; a dead or stale handle is ignored
    bool alive(entity e) const;
    std::size_t entity_count() const { return m_alive_count; }

    // --- components
    template <class T>
    T& emplace(entity e, T value = {}) {
        require_alive(e, "emplace");
        return table<T>().emplace(e, value);
    }
    template <class T>
    void remove(entity e) {
        if (auto* t = find_table<T>()) t->remove(e);
    }
    template <class T>
    bool has(entity e) const {
        const auto* t = find_table<T>();
        return t && t->contains(e);
    }
    template <class T>
    T& get(entity e) {
        return table<T>().get(e);
    }
    template <class T>
    const T& get(entity e) const {
        return table<T>().get(e);
    }
    template <class T>
    T* try_get(entity e) {
        auto* t = find_table<T>();
        return t ? t->try_get(e) : nullptr;
    }
    template <class T>
    const T* try_get(entity e) const {
        const auto* t = find_table<T>();
        return t ? t->try_get(e) : nullptr;
    }

    // Created on first use. The const overload never creates: an unused type yields a shared
    // empty table, so read-only code can ask for anything without mutating the world.
    template <class T>
    component_table<T>& table() {
        const std::size_t id = type_id<T>();
        if (id >= m_tables.size()) m_tables.resize(id + 1);
        if (!m_tables[id]) m_tables[id] = std::make_unique<component_table<T>>();
        return static_cast<component_table<T>&>(*m_tables[id]);
    }
    template <class T>
    const component_table<T>& table() const {
        static const component_table<T> k_empty;
        const auto* t = find_table<T>();
        return t ? *t : k_empty;
    }

    // The component of the one entity that has T (camera, sun, environment).
    template <class T>
    T& single() {
        return table<T>().data()[checked_single_index(table<T>().size(), typeid(T).name())];
    }
    template <class T>
    const T& single() const {
        return table<T>().data()[checked_single_index(table<T>().size(), typeid(T).name())];
    }
    template <class T>
    entity single_entity() const {
        return table<T>().entities()[checked_single_index(table<T>().size(), typeid(T).name())];
    }

    // --- queries: Ts may be const (read) or not (write); the first type drives the iteration.
    template <class... Ts>
    ecs::query<Ts...> query() {
        return make_query<Ts...>(std::tuple{&table<std::remove_const_t<Ts>>()...});
    }
    template <class... Ts>
    ecs::query<const Ts...> query() const {
        return make_query<const Ts...>(std::tuple{&table<std::remove_const_t<Ts>>()...});
    }

    // Reorders each Others table so entities shared with Driver sit at Driver's dense indices.
    // Afterwards a query<Driver, Others...> is aligned iff every Driver entity has all Others.
    // O(n) swaps; call it at a phase boundary (e.g. after spawning).
    template <class Driver, class... Others>
    void align() {
        static_assert(detail::unique_v<Driver, Others...>, "ecs::world::align lists a type twice");
        const component_table<Driver>& driver = table<Driver>();
        (align_to(driver.entities(), table<Others>()), ...);
    }

    // --- resources: type-erased so they may own containers.
    template <class T>
    T& set_resource(T value) {
        const std::size_t id = type_id<T>();
        if (id >= m_resources.size()) m_resources.resize(id + 1);
        resource_ptr& held = m_resources[id];
        // Assigning into an existing resource keeps its address, so references stay valid.
        if (held) return *static_cast<T*>(held.get()) = std::move(value);
        held = resource_ptr(new T(std::move(value)), erased_deleter{&destroy_resource<T>});
        return *static_cast<T*>(held.get());
    }
    template <class T>
    T* try_resource() {
        const std::size_t id = type_id<T>();
        return id < m_resources.size() ? static_cast<T*>(m_resources[id].get()) : nullptr;
    }
    template <class T>
    const T* try_resource() const {
        return const_cast<world*>(this)->try_resource<T>();
    }
    template <class T>
    T& resource() {
        T* r = try_resource<T>();
        if (!r)
            throw std::logic_error(std::string("ecs::world::resource: not set: ") +
                                   typeid(T).name());
        return *r;
    }
    template <class T>
    const T& resource() const {
        return const_cast<world*>(this)->resource<T>();
    }
    template <class T>
    bool has_resource() const {
        return try_resource<T>() != nullptr;
    }

    // The frame being played; set by the player, read by systems for hash(seed, entity, frame).
    std::uint64_t frame_index() const { return m_frame_index; }
    void set_frame_index(std::uint64_t frame) { m_frame_index = frame; }

    // How many entities one task of a system's parallel loop handles (system_context::chunk()).
    // Chunking never depends on the thread count, so results do not depend on this either: a
    // smaller chunk only splits the same loops into more tasks and exercises the same per-chunk
    // paths (counts, prefix sums, merges) on a small scene. Set it between frames.
    std::size_t chunk_size() const { return m_chunk_size; }
    void set_chunk_size(std::size_t chunk);  // throws std::invalid_argument for 0

private:
    struct slot {
        std::uint32_t generation = 0;
        bool alive = false;
    };
    struct erased_deleter {
        void (*destroy)(void*) = nullptr;
        void operator()(void* p) const { destroy(p); }
    };
    using resource_ptr = std::unique_ptr<void, erased_deleter>;
    struct alignment_cache;

    template <class T>
    static void destroy_resource(void* p) {
        delete static_cast<T*>(p);
    }

    template <class T>
    component_table<T>* find_table() const {
        const std::size_t id = type_id<T>();
        if (id >= m_tables.size() || !m_tables[id]) return nullptr;
        return static_cast<component_table<T>*>(m_tables[id].get());
    }

    template <class... Ts, class Tables>
    ecs::query<Ts...> make_query(Tables tables) const {
        bool aligned = true;
        const table_base& driver = *std::get<0>(tables);
        std::apply(
            [&](const auto*, const auto*... others) {
                ((aligned = aligned && tables_aligned(driver, *others)), ...);
            },
            tables);
        return ecs::query<Ts...>(tables, aligned);
    }

    template <class T>
    static void align_to(std::span<const entity> order, component_table<T>& other) {
        std::size_t next = 0;
        for (const entity e : order) {
            const std::size_t at = other.index_of(e);
            if (at != k_npos) other.swap_dense(at, next++);
        }
    }

    void require_alive(entity e, const char* operation) const;
    static std::size_t checked_single_index(std::size_t size, const char* type_name);
    bool tables_aligned(const table_base& driver, const table_base& other) const;

    std::vector<slot> m_slots;
    std::vector<std::uint32_t> m_free;  // recycled slot indices, reused last-in first-out
    std::size_t m_alive_count = 0;
    std::vector<std::unique_ptr<table_base>> m_tables;  // indexed by type_id
    std::vector<resource_ptr> m_resources;              // indexed by type_id
    std::unique_ptr<alignment_cache> m_alignment;
    std::uint64_t m_frame_index = 0;
    std::size_t m_chunk_size = k_default_chunk;
};

}  // namespace sylva::ecs
