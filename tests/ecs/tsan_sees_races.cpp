// Built only under ThreadSanitizer (tests/CMakeLists.txt): proves that the hand-off edges
// ecs/tsan_handoff.h states for oneTBB do not blind TSan to a real race. Chunks of one
// ecs::parallel_for write the same int without synchronising; the test passes only when TSan
// reports that data race (PASS_REGULAR_EXPRESSION), so an annotation that ordered one task after
// another would fail it.
#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>

#include "ecs/executor.h"
#include "ecs/parallel.h"

int main() {
    sylva::ecs::executor exec(2);
    int shared = 0;
    std::atomic<int> workers_seen{0};
    const std::thread::id caller = std::this_thread::get_id();
    exec.run([&] {
        sylva::ecs::parallel_for(64, 1, [&](std::size_t, std::size_t, std::size_t chunk) {
            if (std::this_thread::get_id() != caller) workers_seen.fetch_add(1);
            // Long enough that the second thread takes chunks while the first still runs.
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
            shared += int(chunk);  // the race
        });
    });
    std::printf("sum %d, chunks on a worker %d\n", shared, workers_seen.load());
    return 0;
}
