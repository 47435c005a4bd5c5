#pragma once
// The happens-before edges of oneTBB's task hand-offs, stated to ThreadSanitizer.
//
// Why this exists: Debian's libtbb is not built with -fsanitize=thread, so TSan cannot see the
// synchronisation inside it. Data the caller writes before tbb::parallel_for and a worker reads
// in a chunk, or a task's output the caller reads after wait(), then look like races
// (docs/hardening.md). oneTBB guarantees both orders: a task starts after it was spawned, and
// wait() returns after every task ended. task_handoff states exactly those two edges and nothing
// else. No task acquires what another task released, so TSan still reports two chunks or two
// tasks that touch the same data without synchronising. Without TSan it compiles to nothing.
//
//   task_handoff handoff;
//   handoff.spawn();                                   // the caller, before handing tasks over
//   tbb::parallel_for(..., [&](...) { const auto in = handoff.task(); ... });
//   handoff.joined();                                  // the caller, after every task ended

#if defined(__SANITIZE_THREAD__)
#define SYLVA_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define SYLVA_TSAN 1
#endif
#endif

#ifdef SYLVA_TSAN
extern "C" void __tsan_acquire(void* addr);
extern "C" void __tsan_release(void* addr);
#endif

namespace sylva::ecs {

// Release on an address: what this thread did so far happens before any later acquire of it.
inline void tsan_release([[maybe_unused]] const void* token) {
#ifdef SYLVA_TSAN
    __tsan_release(const_cast<void*>(token));
#endif
}

inline void tsan_acquire([[maybe_unused]] const void* token) {
#ifdef SYLVA_TSAN
    __tsan_acquire(const_cast<void*>(token));
#endif
}

class task_handoff {
public:
    // Lives from a task's first statement to its last (an exception included).
    class task_scope {
    public:
        explicit task_scope(const task_handoff& h) : m_handoff(h) { tsan_acquire(&h.m_spawned); }
        ~task_scope() { tsan_release(&m_handoff.m_ended); }
        task_scope(const task_scope&) = delete;
        task_scope& operator=(const task_scope&) = delete;

    private:
        const task_handoff& m_handoff;
    };

    void spawn() const { tsan_release(&m_spawned); }
    [[nodiscard]] task_scope task() const { return task_scope(*this); }
    void joined() const { tsan_acquire(&m_ended); }

private:
    // Only their addresses matter: the spawner's edge and the tasks' edge are kept apart so
    // that no task inherits another task's history.
    char m_spawned = 0;
    char m_ended = 0;
};

}  // namespace sylva::ecs
