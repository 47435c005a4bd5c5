#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "ecs/world.h"

namespace sylva::ecs {
namespace {

struct position {
    float x = 0.0f;
};
struct velocity {
    float dx = 0.0f;
};
struct tag {
    int id = 0;
};

std::vector<entity> visited(query<const position, const velocity> q) {
    std::vector<entity> out;
    q.each([&](entity e, const position&, const velocity&) { out.push_back(e); });
    return out;
}

// Entities created and given components in the same order: aligned by construction.
std::vector<entity> spawn_aligned(world& w, std::size_t n) {
    std::vector<entity> es;
    for (std::size_t i = 0; i < n; ++i) {
        const entity e = w.create();
        w.emplace<position>(e, {float(i)});
        w.emplace<velocity>(e, {float(i) * 10.0f});
        es.push_back(e);
    }
    return es;
}

TEST(query, visits_exactly_entities_having_all_components) {
    world w;
    const entity both = w.create();
    const entity only_position = w.create();
    const entity only_velocity = w.create();
    w.emplace<velocity>(only_velocity);
    w.emplace<position>(only_position);
    w.emplace<position>(both);
    w.emplace<velocity>(both);
    const auto q = w.query<const position, const velocity>();
    EXPECT_FALSE(q.aligned());
    EXPECT_EQ(q.size(), 2u);  // candidates: the driver's size
    EXPECT_EQ(visited(q), std::vector<entity>{both});
}

TEST(query, components_created_in_same_order_are_aligned) {
    world w;
    spawn_aligned(w, 10);
    EXPECT_TRUE((w.query<const position, const velocity>().aligned()));
}

TEST(query, aligned_fast_path_equals_lookup_fallback) {
    world w;
    spawn_aligned(w, 100);
    const auto fast = w.query<const position, const velocity>();
    ASSERT_TRUE(fast.aligned());
    const query<const position, const velocity> slow(
        {&std::as_const(w).table<position>(), &std::as_const(w).table<velocity>()}, false);
    std::vector<float> a, b;
    fast.each([&](entity, const position& p, const velocity& v) { a.push_back(p.x + v.dx); });
    slow.each([&](entity, const position& p, const velocity& v) { b.push_back(p.x + v.dx); });
    EXPECT_EQ(a, b);
    EXPECT_EQ(visited(fast), visited(slow));
}

TEST(query, writes_through_non_const_components) {
    world w;
    spawn_aligned(w, 5);
    w.query<position, const velocity>().each(
        [](entity, position& p, const velocity& v) { p.x += v.dx; });
    EXPECT_FLOAT_EQ(w.table<position>().data()[2].x, 22.0f);
}

TEST(query, removal_breaks_alignment_and_fallback_stays_correct) {
    world w;
    const auto es = spawn_aligned(w, 6);
    w.remove<velocity>(es[1]);  // velocity swap-removes; position keeps es[1]
    const auto q = w.query<const position, const velocity>();
    EXPECT_FALSE(q.aligned());
    std::vector<entity> expected(es.begin(), es.end());
    expected.erase(expected.begin() + 1);
    EXPECT_EQ(visited(q), expected);
}

TEST(query, align_makes_shuffled_tables_aligned) {
    world w;
    std::vector<entity> es;
    for (int i = 0; i < 8; ++i) es.push_back(w.create());
    for (int i = 0; i < 8; ++i) w.emplace<position>(es[i], {float(i)});
    for (int i = 7; i >= 0; --i) w.emplace<velocity>(es[i], {float(i)});  // reverse order
    w.emplace<velocity>(w.create());  // extra velocity-only entity: must not break alignment
    EXPECT_FALSE((w.query<const position, const velocity>().aligned()));
    w.align<position, velocity>();
    const auto q = w.query<const position, const velocity>();
    ASSERT_TRUE(q.aligned());
    q.each([](entity, const position& p, const velocity& v) { EXPECT_FLOAT_EQ(p.x, v.dx); });
    EXPECT_EQ(visited(q), es);
}

TEST(query, align_after_destroy_restores_fast_path) {
    world w;
    const auto es = spawn_aligned(w, 6);
    w.emplace<tag>(es[0]);  // tag-only table of a different size
    w.destroy(es[2]);
    w.remove<position>(es[4]);
    w.align<velocity, position>();
    EXPECT_FALSE((w.query<const velocity, const position>().aligned()));  // es[4] lacks position
    EXPECT_TRUE((w.query<const position, const velocity>().aligned()));
}

TEST(query, column_spans_match_each_when_aligned) {
    world w;
    spawn_aligned(w, 4);
    const auto q = w.query<const position, velocity>();
    const std::span<velocity> v = q.column<velocity>();
    const std::span<const position> p = q.column<const position>();
    ASSERT_EQ(v.size(), 4u);
    EXPECT_FLOAT_EQ(p[3].x, 3.0f);
    EXPECT_FLOAT_EQ(v[3].dx, 30.0f);
}

TEST(query, column_of_unaligned_query_throws_except_driver) {
    world w;
    const auto es = spawn_aligned(w, 4);
    w.remove<velocity>(es[0]);
    const auto q = w.query<const position, const velocity>();
    EXPECT_NO_THROW(q.column<const position>());
    EXPECT_THROW(q.column<const velocity>(), std::logic_error);
}

TEST(query, each_chunk_covers_a_dense_sub_range) {
    world w;
    const auto es = spawn_aligned(w, 10);
    std::vector<entity> out;
    w.query<const position, const velocity>().each_chunk(
        3, 6, [&](entity e, const position&, const velocity&) { out.push_back(e); });
    EXPECT_EQ(out, (std::vector<entity>{es[3], es[4], es[5]}));
}

TEST(query, const_world_query_over_unused_type_is_empty) {
    world w;
    spawn_aligned(w, 3);
    const world& cw = w;
    EXPECT_EQ((cw.query<position, tag>().size()), 3u);
    int calls = 0;
    cw.query<position, tag>().each([&](entity, const position&, const tag&) { ++calls; });
    EXPECT_EQ(calls, 0);
    EXPECT_EQ((cw.query<tag, position>().size()), 0u);
}

}  // namespace
}  // namespace sylva::ecs
