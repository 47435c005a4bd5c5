#pragma once
// Owns the thread budget of a run: a tbb::task_arena with exactly `threads` concurrency. Every
// parallel_for and system task started inside run() stays in that arena, so "--threads 2" means
// two threads end to end. Results do not depend on it (see parallel.h); only speed does.
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/task_arena.h>

#include <memory>
#include <utility>

#include "ecs/tsan_handoff.h"

namespace sylva::ecs {

class executor {
public:
    explicit executor(int threads);  // threads <= 0: TBB's default concurrency
    executor(const executor&) = delete;
    executor& operator=(const executor&) = delete;

    int threads() const { return m_threads; }

    // Runs f inside the arena on the calling thread when it can join (TBB reserves one slot for
    // it); calling run() again from inside f just calls f.
    template <class F>
    decltype(auto) run(F&& f) {
        // f may run on a worker when the arena has no slot for the caller (ecs/tsan_handoff.h).
        const task_handoff handoff;
        handoff.spawn();
        struct joined_on_return {
            const task_handoff& h;
            ~joined_on_return() { h.joined(); }
        } joined{handoff};
        return m_arena->execute([&]() -> decltype(auto) {
            const auto in_task = handoff.task();
            return f();
        });
    }

    tbb::task_arena& arena() { return *m_arena; }

private:
    int m_threads;
    // TBB caps its worker pool at the hardware thread count; asking for more threads than cores
    // (determinism tests run 4 threads on 2 cores) needs the cap raised, or the arena silently
    // gets fewer workers.
    std::unique_ptr<tbb::global_control> m_worker_limit;
    std::unique_ptr<tbb::task_arena> m_arena;
};

}  // namespace sylva::ecs
