#pragma once
// What a running system sees of the world: exactly the types it declared. Reaching for anything
// else is a compile error, raised by the static_asserts below ("... not declared in reads<> or
// writes<> ..."), so a system's declaration is always a truthful input to the scheduler's graph.
// Read access (read, single, resource, const query types) needs T in reads<> or writes<>;
// write access (write, single_mut, resource_mut, non-const query types) needs T in writes<>.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include "ecs/access.h"
#include "ecs/command_buffer.h"
#include "ecs/parallel.h"
#include "ecs/world.h"

namespace sylva::ecs {

// One parallel loop a system ran in a frame: the items it covered, the chunk size it cut them
// by, and how many chunk tasks really ran (counted as they ran, not computed). The schedule
// keeps these per system (schedule::last_loops) so a test can prove which loops crossed chunk
// boundaries; counting costs one relaxed atomic add per chunk.
struct loop_record {
    std::size_t count = 0;
    std::size_t chunk = 0;
    std::size_t chunks_run = 0;
    friend bool operator==(const loop_record&, const loop_record&) = default;
};

template <class S>
class system_context {
    using traits = system_traits<S>;

public:
    // `loops` (may be null) receives a loop_record per parallel_for this system runs.
    system_context(world& w, command_buffer& commands, std::vector<loop_record>* loops = nullptr)
        : m_world(w), m_commands(commands), m_loops(loops) {}

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

    // Entities per task of a parallel loop over entity tables: the world's chunk size
    // (world::chunk_size, k_default_chunk unless set). Loops over entities use it, so one
    // setting splits every such loop of the frame the same way.
    std::size_t chunk() const { return m_world.chunk_size(); }

    // ecs::parallel_for over [0, count) in chunks of chunk(); f(begin, end, chunk_index).
    template <class F>
    void parallel_for(std::size_t count, F&& f) const {
        parallel_for(count, chunk(), std::forward<F>(f));
    }
    // The same with a chunk in other units (e.g. leaf tiles); recorded like the above.
    template <class F>
    void parallel_for(std::size_t count, std::size_t chunk, F&& f) const {
        if (!m_loops) {
            ecs::parallel_for(count, chunk, std::forward<F>(f));
            return;
        }
        std::atomic<std::size_t> ran{0};
        ecs::parallel_for(count, chunk, [&](std::size_t begin, std::size_t end, std::size_t c) {
            f(begin, end, c);
            ran.fetch_add(1, std::memory_order_relaxed);
        });
        m_loops->push_back({count, chunk, ran.load(std::memory_order_relaxed)});
    }

private:
    world& m_world;
    command_buffer& m_commands;
    std::vector<loop_record>* m_loops;
};

}  // namespace sylva::ecs
