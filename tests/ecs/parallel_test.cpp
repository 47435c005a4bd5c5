#include "ecs/parallel.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

#include "ecs/executor.h"

namespace sylva::ecs {
namespace {

using chunk_record = std::tuple<std::size_t, std::size_t, std::size_t>;

std::vector<chunk_record> record_chunks(int threads, std::size_t count, std::size_t chunk) {
    executor exec(threads);
    std::vector<chunk_record> chunks(chunk_count(count, chunk));
    exec.run([&] {
        parallel_for(count, chunk, [&](std::size_t begin, std::size_t end, std::size_t c) {
            chunks[c] = {begin, end, c};
        });
    });
    return chunks;
}

TEST(parallel_for, chunk_boundaries_are_fixed_by_count_and_chunk) {
    const auto chunks = record_chunks(2, 10, 4);
    EXPECT_EQ(chunks, (std::vector<chunk_record>{{0, 4, 0}, {4, 8, 1}, {8, 10, 2}}));
}

TEST(parallel_for, chunk_boundaries_identical_for_1_2_4_threads) {
    const auto one = record_chunks(1, 100'003, 4096);
    EXPECT_EQ(one, record_chunks(2, 100'003, 4096));
    EXPECT_EQ(one, record_chunks(4, 100'003, 4096));
}

TEST(parallel_for, empty_range_calls_nothing_and_zero_chunk_throws) {
    int calls = 0;
    parallel_for(0, 16, [&](std::size_t, std::size_t, std::size_t) { ++calls; });
    EXPECT_EQ(calls, 0);
    EXPECT_THROW(parallel_for(10, 0, [](std::size_t, std::size_t, std::size_t) {}),
                 std::invalid_argument);
}

TEST(parallel_for, every_index_visited_once) {
    std::vector<int> hits(50'000, 0);
    executor exec(4);
    exec.run([&] {
        parallel_for(hits.size(), 1000, [&](std::size_t begin, std::size_t end, std::size_t) {
            for (std::size_t i = begin; i < end; ++i) ++hits[i];
        });
    });
    EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), 50'000);
}

// Values spanning many magnitudes, so any change in summation order changes the low bits.
double reduce_sum(int threads, const std::vector<double>& values) {
    executor exec(threads);
    return exec.run([&] {
        return parallel_reduce(
            values.size(), 1024, 0.0,
            [&](std::size_t begin, std::size_t end, std::size_t) {
                double s = 0.0;
                for (std::size_t i = begin; i < end; ++i) s += values[i];
                return s;
            },
            [](double a, double b) { return a + b; });
    });
}

TEST(parallel_reduce, floating_point_sum_bit_identical_for_1_2_4_threads) {
    std::vector<double> values(200'000);
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = std::sin(double(i)) * std::pow(10.0, double(i % 17) - 8.0);
    const auto one = std::bit_cast<std::uint64_t>(reduce_sum(1, values));
    EXPECT_EQ(one, std::bit_cast<std::uint64_t>(reduce_sum(2, values)));
    EXPECT_EQ(one, std::bit_cast<std::uint64_t>(reduce_sum(4, values)));
}

TEST(parallel_reduce, caller_scratch_holds_per_chunk_partials) {
    std::vector<int> partials;
    const int total = parallel_reduce(
        10, 3, 0, [](std::size_t begin, std::size_t end, std::size_t) { return int(end - begin); },
        [](int a, int b) { return a + b; }, partials);
    EXPECT_EQ(total, 10);
    EXPECT_EQ(partials, (std::vector<int>{3, 3, 3, 1}));
}

TEST(executor, arena_has_exactly_the_requested_concurrency) {
    for (int threads : {1, 2, 4}) {
        executor exec(threads);
        EXPECT_EQ(exec.threads(), threads);
        EXPECT_EQ(exec.run([] { return tbb::this_task_arena::max_concurrency(); }), threads);
    }
}

}  // namespace
}  // namespace sylva::ecs
