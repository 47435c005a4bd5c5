#pragma once
// Deferred structural changes. Systems may not create, destroy, emplace or remove while a phase
// runs (other systems are iterating the tables), so they record here; the scheduler applies each
// system's buffer at the end of the phase, in system registration order, and a buffer applies
// its commands in the order they were recorded. That fixed order is what keeps the result
// independent of thread timing.
//
// create() returns a placeholder handle that is only meaningful as an argument to this same
// buffer (emplace/remove/destroy); apply() turns placeholders into real entities and created()
// lists those in create() order. Placeholders stored inside component values are not patched.
//
// A buffer is not thread-safe: for per-chunk recording, give each chunk its own buffer (indexed
// by chunk) and append() them in chunk order.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>

#include "ecs/entity.h"

namespace sylva::ecs {

class world;

class command_buffer {
public:
    entity create();
    void destroy(entity e);

    template <class T>
    void emplace(entity e, const T& value = {}) {
        static_assert(std::is_trivially_copyable_v<T>, "ecs components are plain data");
        const std::size_t offset = m_payload.size();
        m_payload.resize(offset + sizeof(T));
        std::memcpy(m_payload.data() + offset, &value, sizeof(T));
        m_commands.push_back({op::emplace, e, &apply_emplace<T>, offset});
    }

    template <class T>
    void remove(entity e) {
        m_commands.push_back({op::remove, e, &apply_remove<T>, 0});
    }

    // Moves other's commands after this buffer's own; other is left empty (capacity kept).
    void append(command_buffer& other);

    // Applies in record order, then clears. Commands aimed at an entity that is dead by the time
    // they run (destroyed earlier in the buffer, or stale when recorded) are skipped.
    void apply(world& w);

    std::span<const entity> created() const { return m_created; }
    std::size_t size() const { return m_commands.size(); }
    bool empty() const { return m_commands.empty(); }
    void clear();

    static constexpr bool is_placeholder(entity e) {
        return e.generation == k_placeholder_generation && !e.is_null();
    }

private:
    // A real slot would need 2^32 - 1 recycles to reach this generation.
    static constexpr std::uint32_t k_placeholder_generation = 0xFFFF'FFFFu;

    enum class op : std::uint8_t { create, destroy, emplace, remove };
    using apply_fn = void (*)(world&, entity, const std::byte*);
    struct command {
        op kind;
        entity target;
        apply_fn apply;
        std::size_t payload;  // byte offset of the component value in m_payload
    };

    template <class T>
    static void apply_emplace(world& w, entity e, const std::byte* bytes);
    template <class T>
    static void apply_remove(world& w, entity e, const std::byte*);

    entity resolve(entity e) const;

    std::vector<command> m_commands;
    std::vector<std::byte> m_payload;
    std::uint32_t m_placeholders = 0;
    std::vector<entity> m_created;
};

}  // namespace sylva::ecs

#include "ecs/world.h"

namespace sylva::ecs {

template <class T>
void command_buffer::apply_emplace(world& w, entity e, const std::byte* bytes) {
    // bit_cast rather than a placement copy: no default constructor or alignment needed.
    std::array<std::byte, sizeof(T)> raw;
    std::memcpy(raw.data(), bytes, sizeof(T));
    w.emplace<T>(e, std::bit_cast<T>(raw));
}

template <class T>
void command_buffer::apply_remove(world& w, entity e, const std::byte*) {
    w.remove<T>(e);
}

}  // namespace sylva::ecs
