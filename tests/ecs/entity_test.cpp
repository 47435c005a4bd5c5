#include <gtest/gtest.h>

#include <unordered_set>

#include "ecs/world.h"

namespace sylva::ecs {
namespace {

struct position {
    float x = 0.0f;
};

TEST(entity, default_constructed_is_null) {
    const entity e;
    EXPECT_TRUE(e.is_null());
    EXPECT_EQ(e, k_null_entity);
    world w;
    EXPECT_FALSE(w.alive(e));
}

TEST(entity, create_gives_distinct_live_handles) {
    world w;
    const entity a = w.create();
    const entity b = w.create();
    EXPECT_NE(a, b);
    EXPECT_TRUE(w.alive(a));
    EXPECT_TRUE(w.alive(b));
    EXPECT_EQ(w.entity_count(), 2u);
}

TEST(entity, destroy_makes_handle_stale_even_after_slot_reuse) {
    world w;
    const entity old = w.create();
    w.destroy(old);
    EXPECT_FALSE(w.alive(old));
    const entity reused = w.create();
    EXPECT_EQ(reused.index, old.index);            // the slot is recycled...
    EXPECT_NE(reused.generation, old.generation);  // ...under a new generation
    EXPECT_TRUE(w.alive(reused));
    EXPECT_FALSE(w.alive(old));
    EXPECT_EQ(w.entity_count(), 1u);
}

TEST(entity, stale_handle_does_not_see_new_occupants_components) {
    world w;
    const entity old = w.create();
    w.emplace<position>(old, {1.0f});
    w.destroy(old);
    const entity reused = w.create();
    w.emplace<position>(reused, {2.0f});
    EXPECT_FALSE(w.has<position>(old));
    EXPECT_EQ(w.try_get<position>(old), nullptr);
    EXPECT_FLOAT_EQ(w.get<position>(reused).x, 2.0f);
}

TEST(entity, destroying_stale_handle_is_ignored) {
    world w;
    const entity old = w.create();
    w.destroy(old);
    const entity reused = w.create();
    w.destroy(old);
    EXPECT_TRUE(w.alive(reused));
    EXPECT_EQ(w.entity_count(), 1u);
}

TEST(entity, emplace_on_dead_entity_throws) {
    world w;
    const entity e = w.create();
    w.destroy(e);
    EXPECT_THROW(w.emplace<position>(e), std::logic_error);
}

TEST(entity, hashes_by_index_and_generation) {
    std::unordered_set<entity> set{{1, 0}, {1, 1}, {2, 0}};
    EXPECT_EQ(set.size(), 3u);
}

}  // namespace
}  // namespace sylva::ecs
