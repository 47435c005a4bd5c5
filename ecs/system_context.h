#pragma once
// What a running system sees of the world: exactly the types it declared. Reaching for anything
// else is a compile error, raised by the static_asserts below ("... not declared in reads<> or
// writes<> ..."), so a system's declaration is always a truthful input to the scheduler's graph.
// Read access (read, single, resource, const query types) needs T in reads<> or writes<>;
// write access (write, single_mut, resource_mut, non-const query types) needs T in writes<>.
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "ecs/access.h"
#include "ecs/command_buffer.h"
#include "ecs/parallel.h"
#include "ecs/world.h"

namespace sylva::ecs {

template <class S>
class system_context {
    using traits = system_traits<S>;

public:
    system_context(world& w, command_buffer& commands) : m_world(w), m_commands(commands) {}

    template <class T>
    const component_table<T>& read() const {
        static_assert(traits::template k_reads<T>,
                      "ecs::system_context::read<T>: T not declared in reads<> or writes<>");
        return std::as_const(m_world).template table<T>();
    }
    template <class T>
    component_table<T>& write() {
        static_assert(traits::template k_writes<T>,
                      "ecs::system_context::write<T>: T not declared in writes<>");
        return m_world.template table<T>();
    }

    template <class... Ts>
    ecs::query<Ts...> query() {
        static_assert(
            ((std::is_const_v<Ts> ? traits::template k_reads<Ts>
                                  : traits::template k_writes<Ts>)&&...),
            "ecs::system_context::query: a const type must be declared in reads<> or writes<>, "
            "a non-const type in writes<>");
        return m_world.template query<Ts...>();
    }

    template <class T>
    const T& single() const {
        static_assert(traits::template k_reads<T>,
                      "ecs::system_context::single<T>: T not declared in reads<> or writes<>");
        return std::as_const(m_world).template single<T>();
    }
    template <class T>
    T& single_mut() {
        static_assert(traits::template k_writes<T>,
                      "ecs::system_context::single_mut<T>: T not declared in writes<>");
        return m_world.template single<T>();
    }
    template <class T>
    entity single_entity() const {
        static_assert(
            traits::template k_reads<T>,
            "ecs::system_context::single_entity<T>: T not declared in reads<> or writes<>");
        return m_world.template single_entity<T>();
    }

    template <class T>
    const T& resource() const {
        static_assert(traits::template k_reads<T>,
                      "ecs::system_context::resource<T>: T not declared in reads<> or writes<>");
        return std::as_const(m_world).template resource<T>();
    }
    template <class T>
    const T* try_resource() const {
        static_assert(
            traits::template k_reads<T>,
            "ecs::system_context::try_resource<T>: T not declared in reads<> or writes<>");
        return std::as_const(m_world).template try_resource<T>();
    }
    template <class T>
    T& resource_mut() {
        static_assert(traits::template k_writes<T>,
                      "ecs::system_context::resource_mut<T>: T not declared in writes<>");
        return m_world.template resource<T>();
    }

    // Structural changes, applied at the end of this system's phase (see command_buffer.h).
    command_buffer& commands() { return m_commands; }
    // Liveness only changes at phase boundaries, so it needs no declaration.
    bool alive(entity e) const { return m_world.alive(e); }
    std::uint64_t frame_index() const { return m_world.frame_index(); }

    template <class F>
    void parallel_for(std::size_t count, std::size_t chunk, F&& f) const {
        ecs::parallel_for(count, chunk, std::forward<F>(f));
    }

private:
    world& m_world;
    command_buffer& m_commands;
};

}  // namespace sylva::ecs
