#pragma once
// Deterministic chunked loops. Chunk boundaries are a function of (count, chunk) only — never of
// the thread count — so per-chunk outputs (counts, partial sums, command buffers) merged in chunk
// order give bit-identical results on 1 or 64 threads. Work runs in the caller's current task
// arena, i.e. with the executor's thread count when called from a scheduled system.
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

#include "ecs/tsan_handoff.h"

namespace sylva::ecs {

inline constexpr std::size_t k_default_chunk = 4096;

constexpr std::size_t chunk_count(std::size_t count, std::size_t chunk) {
    return chunk == 0 ? 0 : (count + chunk - 1) / chunk;
}

// f(begin, end, chunk_index) for chunks [i*chunk, min((i+1)*chunk, count)).
template <class F>
void parallel_for(std::size_t count, std::size_t chunk, F&& f) {
    if (chunk == 0) throw std::invalid_argument("ecs::parallel_for: chunk must be positive");
    const std::size_t chunks = chunk_count(count, chunk);
    if (chunks == 0) return;
    if (chunks == 1) {  // skip the task machinery for small inputs
        f(std::size_t{0}, count, std::size_t{0});
        return;
    }
    // simple_partitioner with grain 1: one task per chunk index, never merged or split further.
    const task_handoff handoff;
    handoff.spawn();
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, chunks, 1),
        [&](const tbb::blocked_range<std::size_t>& r) {
            const auto in_task = handoff.task();
            for (std::size_t c = r.begin(); c != r.end(); ++c)
                f(c * chunk, std::min(count, (c + 1) * chunk), c);
        },
        tbb::simple_partitioner{});
    handoff.joined();
}

// f(i) for every i in [0, count), in any order, on any thread of the arena: for loops whose
// iterations are independent (the bakers). Partitioned as tbb::parallel_for(0, count, f) is,
// but the body reaches TBB by value, so the task acquires its hand-off before it reads anything
// the caller wrote (ecs/tsan_handoff.h; the index form would read f through a reference first).
template <class F>
void parallel_for_each_index(std::size_t count, F&& f) {
    const task_handoff handoff;
    handoff.spawn();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          const auto in_task = handoff.task();
                          for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
                      });
    handoff.joined();
}

// map(begin, end, chunk_index) -> T per chunk, stored by chunk index, then folded left to right:
// combine(combine(combine(identity, p0), p1), ...). Floating-point sums are therefore the same
// for any thread count. `partials` is caller-owned scratch so a warm frame does not allocate.
template <class T, class Map, class Combine>
T parallel_reduce(std::size_t count, std::size_t chunk, T identity, Map&& map, Combine&& combine,
                  std::vector<T>& partials) {
    partials.assign(chunk_count(count, chunk), identity);
    parallel_for(count, chunk, [&](std::size_t begin, std::size_t end, std::size_t c) {
        partials[c] = map(begin, end, c);
    });
    T result = std::move(identity);
    for (const T& part : partials) result = combine(std::move(result), part);
    return result;
}

template <class T, class Map, class Combine>
T parallel_reduce(std::size_t count, std::size_t chunk, T identity, Map&& map, Combine&& combine) {
    std::vector<T> partials;
    return parallel_reduce(count, chunk, std::move(identity), std::forward<Map>(map),
                           std::forward<Combine>(combine), partials);
}

}  // namespace sylva::ecs
