#include "io/once_per_process.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

namespace sylva {
namespace {

TEST(once_per_process, the_first_ask_is_true_and_every_later_one_false) {
    EXPECT_TRUE(first_time_in_process("once test", "a"));
    EXPECT_FALSE(first_time_in_process("once test", "a"));
    EXPECT_FALSE(first_time_in_process("once test", "a"));
    EXPECT_TRUE(first_time_in_process("once test", "b"));
}

TEST(once_per_process, topics_keep_equal_keys_apart) {
    EXPECT_TRUE(first_time_in_process("once topic 1", "key"));
    EXPECT_TRUE(first_time_in_process("once topic 2", "key"));
    // The separator keeps ("ab", "c") and ("a", "bc") apart.
    EXPECT_TRUE(first_time_in_process("once ab", "c"));
    EXPECT_TRUE(first_time_in_process("once a", "bc"));
}

TEST(once_per_process, of_threads_asking_at_once_exactly_one_is_first) {
    std::atomic<int> firsts{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 8; ++t)
        threads.emplace_back([&] {
            for (int k = 0; k < 200; ++k)
                if (first_time_in_process("once threads", std::to_string(k))) ++firsts;
        });
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(firsts.load(), 200);
}

}  // namespace
}  // namespace sylva
