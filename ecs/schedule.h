#pragma once
// Turns system declarations into a per-phase dependency graph and runs one frame of it.
//
// Graph rule (after EnTT's organizer and Bevy's conflict sets, minus Bevy's "any ready order"):
//  - phases run in enum order; between phases every system's command buffer is applied, in
//    registration order;
//  - inside a phase, system j depends on an earlier-registered system i iff they conflict: both
//    write a type, or one writes a type the other reads. Everything else may run concurrently.
//  - a phase containing a main-thread system runs all its systems sequentially, in registration
//    order, on the thread that called run() (GL submission).
// Conflicting systems are thus always ordered by registration, never by timing: together with
// fixed chunking that makes a frame bit-identical for any thread count.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <utility>
#include <vector>

#include "ecs/access.h"
#include "ecs/command_buffer.h"
#include "ecs/executor.h"
#include "ecs/system_context.h"
#include "ecs/world.h"

namespace sylva::ecs {

class schedule {
public:
    schedule();
    ~schedule();
    schedule(const schedule&) = delete;
    schedule& operator=(const schedule&) = delete;

    // Registration order is the tie-break between conflicting systems. Names must be unique.
    template <class S>
    void add() {
        using traits = system_traits<S>;
        static_assert(
            requires(system_context<S> & ctx) { S::run(ctx); },
            "ecs::schedule::add<S>: S needs `static void run(ecs::system_context<S>&)`");
        add_entry(
            system_entry{traits::k_name,
                         traits::k_phase,
                         traits::k_main_thread,
                         detail::list_ids<typename traits::read_list>::get(),
                         detail::list_ids<typename traits::write_list>::get(),
                         &run_system<S>,
                         &prepare_tables<typename traits::read_list, typename traits::write_list>,
                         {},
                         {}});
    }

    // Derives the graph; run() calls it if systems were added since.
    void build();

    // Direct edge `earlier -> later` (same phase, conflicting). Throws on unknown names.
    bool depends_on(std::string_view later, std::string_view earlier) const;
    std::vector<std::string_view> system_names() const;
    std::size_t size() const { return m_systems.size(); }

    // One frame. Call it from inside executor.run() or not — either way the parallel phases run
    // in the executor's arena. Main-thread phases run on this thread, in whatever arena it is in.
    void run(world& w, executor& exec);

    // {name, wall milliseconds} of the last run, in registration order.
    const std::vector<std::pair<std::string_view, double>>& last_timings() const {
        return m_timings;
    }
    // The parallel loops `system` ran in the last run, in the order it ran them (a loop it
    // skipped is absent). Throws on an unknown name.
    const std::vector<loop_record>& last_loops(std::string_view system) const;

private:
    using run_fn = void (*)(world&, command_buffer&, std::vector<loop_record>&);
    using prepare_fn = void (*)(world&);

    struct system_entry {
        std::string_view name;
        phase stage;
        bool main_thread;
        std::vector<std::size_t> reads;
        std::vector<std::size_t> writes;
        run_fn run;
        prepare_fn prepare;
        command_buffer commands;
        std::vector<loop_record> loops;  // last run's; cleared, not freed, each run
    };
    struct phase_group {
        phase stage;
        bool main_thread = false;
        std::vector<std::uint32_t> systems;  // registration order
    };

    template <class S>
    static void run_system(world& w, command_buffer& commands, std::vector<loop_record>& loops) {
        system_context<S> ctx(w, commands, &loops);
        S::run(ctx);
    }

    // Creates every declared component table before the frame, so no table is created (and the
    // world's table vector never grows) while systems run concurrently. Only plain-data types can
    // be components; declared resources are skipped.
    template <class T>
    static void prepare_table(world& w) {
        using bare = std::remove_cv_t<T>;
        if constexpr (std::is_trivially_copyable_v<bare>) w.table<bare>();
    }
    template <class Reads, class Writes>
    static void prepare_tables(world& w) {
        prepare_list(w, static_cast<Reads*>(nullptr));
        prepare_list(w, static_cast<Writes*>(nullptr));
    }
    template <template <class...> class List, class... Ts>
    static void prepare_list(world& w, List<Ts...>*) {
        (prepare_table<Ts>(w), ...);
    }

    void add_entry(system_entry entry);
    std::uint32_t index_of(std::string_view name) const;
    bool conflict(const system_entry& a, const system_entry& b) const;
    void run_phase(const phase_group& group, world& w, executor& exec);
    void run_concurrent(const phase_group& group, world& w);
    void run_one(std::uint32_t system, world& w);

    std::vector<system_entry> m_systems;
    std::vector<phase_group> m_phases;                        // non-empty phases, enum order
    std::vector<std::vector<std::uint32_t>> m_successors;     // by system index
    std::vector<std::vector<std::uint32_t>> m_predecessors;   // by system index
    std::unique_ptr<std::atomic<std::uint32_t>[]> m_pending;  // unfinished predecessors this frame
    std::vector<std::pair<std::string_view, double>> m_timings;
    bool m_built = false;
};

}  // namespace sylva::ecs
