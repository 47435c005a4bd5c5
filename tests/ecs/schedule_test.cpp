#include "ecs/schedule.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/info.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <vector>

#include "ecs/system.h"

namespace sylva::ecs {
namespace {

struct a_comp {
    int v = 0;
};
struct b_comp {
    int v = 0;
};
struct c_comp {
    int v = 0;
};

// Systems that exist only for their declarations (graph tests).
template <char Name, phase P, class R, class W>
struct decl_system {
    static constexpr char k_text[2] = {Name, 0};
    static constexpr std::string_view k_name{k_text, 1};
    static constexpr phase k_phase = P;
    using reads = R;
    using writes = W;
    static void run(system_context<decl_system>&) {}
};

TEST(schedule_graph, write_write_in_same_phase_orders_by_registration) {
    schedule s;
    s.add<decl_system<'a', phase::cull, reads<>, writes<a_comp>>>();
    s.add<decl_system<'b', phase::cull, reads<>, writes<a_comp>>>();
    s.build();
    EXPECT_TRUE(s.depends_on("b", "a"));
    EXPECT_FALSE(s.depends_on("a", "b"));
}

TEST(schedule_graph, read_write_in_same_phase_orders_by_registration_either_way) {
    schedule s;
    s.add<decl_system<'r', phase::cull, reads<a_comp>, writes<>>>();
    s.add<decl_system<'w', phase::cull, reads<>, writes<a_comp>>>();
    s.add<decl_system<'x', phase::cull, reads<const a_comp>, writes<>>>();
    s.build();
    EXPECT_TRUE(s.depends_on("w", "r"));  // reader first: the writer waits for it
    EXPECT_TRUE(s.depends_on("x", "w"));  // writer first: the reader waits
    EXPECT_FALSE(s.depends_on("x", "r"));
}

TEST(schedule_graph, read_read_and_disjoint_types_do_not_create_edges) {
    schedule s;
    s.add<decl_system<'a', phase::cull, reads<a_comp>, writes<b_comp>>>();
    s.add<decl_system<'b', phase::cull, reads<a_comp>, writes<c_comp>>>();
    s.build();
    EXPECT_FALSE(s.depends_on("b", "a"));
}

TEST(schedule_graph, different_phases_have_no_edges) {
    schedule s;
    s.add<decl_system<'a', phase::select, reads<>, writes<a_comp>>>();
    s.add<decl_system<'b', phase::cull, reads<>, writes<a_comp>>>();
    s.build();
    EXPECT_FALSE(s.depends_on("a", "b"));
    EXPECT_FALSE(s.depends_on("b", "a"));
    EXPECT_EQ(s.system_names(), (std::vector<std::string_view>{"a", "b"}));
}

TEST(schedule_graph, duplicate_and_unknown_names_are_rejected) {
    schedule s;
    s.add<decl_system<'a', phase::cull, reads<>, writes<>>>();
    EXPECT_THROW((s.add<decl_system<'a', phase::select, reads<>, writes<>>>()),
                 std::invalid_argument);
    s.build();
    EXPECT_THROW(s.depends_on("a", "nope"), std::invalid_argument);
}

// --- command buffers land at the phase boundary, not before.
struct marker {
    int v = 0;
};
struct seen_in_phase {
    std::size_t same_phase = 99;
    std::size_t later_phase = 99;
};

struct spawn_marker_system {
    static constexpr std::string_view k_name = "spawn_marker";
    static constexpr phase k_phase = phase::cull;
    using writes = ecs::writes<marker>;
    static void run(system_context<spawn_marker_system>& ctx) {
        ctx.commands().emplace<marker>(ctx.commands().create(), {1});
    }
};
struct count_same_phase_system {
    static constexpr std::string_view k_name = "count_same_phase";
    static constexpr phase k_phase = phase::cull;
    using reads = ecs::reads<marker>;
    using writes = ecs::writes<seen_in_phase>;
    static void run(system_context<count_same_phase_system>& ctx) {
        ctx.resource_mut<seen_in_phase>().same_phase = ctx.read<marker>().size();
    }
};
struct count_later_phase_system {
    static constexpr std::string_view k_name = "count_later_phase";
    static constexpr phase k_phase = phase::select;
    using reads = ecs::reads<marker>;
    using writes = ecs::writes<seen_in_phase>;
    static void run(system_context<count_later_phase_system>& ctx) {
        ctx.resource_mut<seen_in_phase>().later_phase = ctx.query<const marker>().size();
    }
};

TEST(schedule_run, command_buffer_applied_at_phase_boundary_not_before) {
    world w;
    w.set_resource(seen_in_phase{});
    schedule s;
    s.add<count_later_phase_system>();  // registered first, but its phase runs later
    s.add<spawn_marker_system>();
    s.add<count_same_phase_system>();
    executor exec(2);
    s.run(w, exec);
    EXPECT_TRUE(s.depends_on("count_same_phase", "spawn_marker"));
    EXPECT_EQ(w.resource<seen_in_phase>().same_phase, 0u);
    EXPECT_EQ(w.resource<seen_in_phase>().later_phase, 1u);
    EXPECT_EQ(w.table<marker>().size(), 1u);
}

// --- independent systems of one phase overlap: each waits (bounded) for the other to start.
std::atomic<int> g_arrived{0};
std::atomic<int> g_met{0};

void rendezvous() {
    g_arrived.fetch_add(1);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (g_arrived.load() < 2 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::yield();
    if (g_arrived.load() >= 2) g_met.fetch_add(1);
}
struct left_system {
    static constexpr std::string_view k_name = "left";
    static constexpr phase k_phase = phase::cull;
    using writes = ecs::writes<a_comp>;
    static void run(system_context<left_system>&) { rendezvous(); }
};
struct right_system {
    static constexpr std::string_view k_name = "right";
    static constexpr phase k_phase = phase::cull;
    using writes = ecs::writes<b_comp>;
    static void run(system_context<right_system>&) { rendezvous(); }
};

TEST(schedule_run, non_conflicting_systems_of_a_phase_overlap) {
    if (tbb::info::default_concurrency() < 2) GTEST_SKIP() << "needs two hardware threads";
    g_arrived = 0;
    g_met = 0;
    world w;
    schedule s;
    s.add<left_system>();
    s.add<right_system>();
    executor exec(2);
    s.run(w, exec);
    EXPECT_FALSE(s.depends_on("right", "left"));
    EXPECT_EQ(g_met.load(), 2);
}

// --- phases are barriers: the later phase starts only after the earlier one finished.
std::atomic<bool> g_slow_done{false};
std::atomic<bool> g_saw_slow_done{false};
struct slow_cull_system {
    static constexpr std::string_view k_name = "slow_cull";
    static constexpr phase k_phase = phase::cull;
    static void run(system_context<slow_cull_system>&) {
        std::this_thread::sleep_for(std::chrono::milliseconds(30));
        g_slow_done = true;
    }
};
struct other_cull_system {
    static constexpr std::string_view k_name = "other_cull";
    static constexpr phase k_phase = phase::cull;
    static void run(system_context<other_cull_system>&) {}
};
struct check_select_system {
    static constexpr std::string_view k_name = "check_select";
    static constexpr phase k_phase = phase::select;
    static void run(system_context<check_select_system>&) { g_saw_slow_done = g_slow_done.load(); }
};

TEST(schedule_run, different_phases_never_run_concurrently) {
    g_slow_done = false;
    g_saw_slow_done = false;
    world w;
    schedule s;
    s.add<check_select_system>();
    s.add<slow_cull_system>();
    s.add<other_cull_system>();
    executor exec(2);
    s.run(w, exec);
    EXPECT_TRUE(g_saw_slow_done.load());
}

// --- main-thread phases run every system on the caller's thread.
struct thread_log {
    std::thread::id gl;
    std::thread::id helper;
};
struct gl_submit_system {
    static constexpr std::string_view k_name = "gl_submit";
    static constexpr phase k_phase = phase::submit;
    static constexpr bool k_main_thread = true;
    using writes = ecs::writes<thread_log>;
    static void run(system_context<gl_submit_system>& ctx) {
        ctx.resource_mut<thread_log>().gl = std::this_thread::get_id();
    }
};
struct submit_helper_system {
    static constexpr std::string_view k_name = "submit_helper";
    static constexpr phase k_phase = phase::submit;
    using writes = ecs::writes<b_comp>;
    using reads = ecs::reads<thread_log>;
    static void run(system_context<submit_helper_system>&) {}
};
struct record_helper_thread_system {
    static constexpr std::string_view k_name = "record_helper";
    static constexpr phase k_phase = phase::submit;
    using writes = ecs::writes<c_comp>;
    static void run(system_context<record_helper_thread_system>& ctx) {
        ctx.write<c_comp>().emplace({0, 0}, {});  // plain memory; just proves write access
    }
};

TEST(schedule_run, main_thread_systems_run_on_calling_thread) {
    world w;
    w.set_resource(thread_log{});
    schedule s;
    s.add<gl_submit_system>();
    s.add<submit_helper_system>();
    executor exec(2);
    for (int frame = 0; frame < 3; ++frame) {
        s.run(w, exec);
        EXPECT_EQ(w.resource<thread_log>().gl, std::this_thread::get_id());
        exec.run([&] { s.run(w, exec); });  // the player's way: inside the executor's arena
        EXPECT_EQ(w.resource<thread_log>().gl, std::this_thread::get_id());
    }
}

TEST(schedule_run, last_timings_has_one_entry_per_system_in_registration_order) {
    world w;
    w.set_resource(thread_log{});
    schedule s;
    s.add<submit_helper_system>();
    s.add<slow_cull_system>();
    s.add<record_helper_thread_system>();
    executor exec(1);
    s.run(w, exec);
    const auto& timings = s.last_timings();
    ASSERT_EQ(timings.size(), 3u);
    EXPECT_EQ(timings[0].first, "submit_helper");
    EXPECT_EQ(timings[1].first, "slow_cull");
    EXPECT_GE(timings[1].second, 25.0);
    EXPECT_EQ(timings[2].first, "record_helper");
}

// --- loop records: which parallel loops a system ran, in how many chunks.
struct chunk_sums {
    std::vector<int> per_chunk;  // the sum of a_comp values in each chunk of the first loop
};
struct two_loops_system {
    static constexpr std::string_view k_name = "two_loops";
    static constexpr phase k_phase = phase::cull;
    using reads = ecs::reads<a_comp>;
    using writes = ecs::writes<chunk_sums>;
    static void run(system_context<two_loops_system>& ctx) {
        const auto& values = ctx.read<a_comp>();
        auto& sums = ctx.resource_mut<chunk_sums>().per_chunk;
        sums.assign(chunk_count(values.size(), ctx.chunk()), 0);
        ctx.parallel_for(values.size(), [&](std::size_t begin, std::size_t end, std::size_t c) {
            for (std::size_t i = begin; i < end; ++i) sums[c] += values.data()[i].v;
        });
        ctx.parallel_for(10, 4, [](std::size_t, std::size_t, std::size_t) {});  // other units
        if (values.size() > 1000) ctx.parallel_for(1, [](std::size_t, std::size_t, std::size_t) {});
    }
};

TEST(schedule_run, loops_are_recorded_with_the_worlds_chunk_and_the_chunks_that_ran) {
    world w;
    for (int i = 0; i < 250; ++i) w.emplace<a_comp>(w.create(), {1});
    w.set_resource(chunk_sums{});
    EXPECT_EQ(w.chunk_size(), k_default_chunk);
    EXPECT_THROW(w.set_chunk_size(0), std::invalid_argument);
    w.set_chunk_size(100);
    schedule s;
    s.add<two_loops_system>();
    executor exec(2);
    exec.run([&] { s.run(w, exec); });
    // 250 entities in chunks of 100: 3 chunks; 10 items in chunks of 4: 3; the skipped loop is
    // absent.
    const std::vector<loop_record> expected = {{250, 100, 3}, {10, 4, 3}};
    EXPECT_EQ(s.last_loops("two_loops"), expected);
    EXPECT_EQ(w.resource<chunk_sums>().per_chunk, (std::vector<int>{100, 100, 50}));
    // The records are the last run's, not accumulated.
    exec.run([&] { s.run(w, exec); });
    EXPECT_EQ(s.last_loops("two_loops"), expected);
    EXPECT_THROW(s.last_loops("no_such_system"), std::invalid_argument);
}

}  // namespace
}  // namespace sylva::ecs
