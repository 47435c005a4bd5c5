#include "ecs/command_buffer.h"

#include <gtest/gtest.h>

#include "ecs/world.h"

namespace sylva::ecs {
namespace {

struct health {
    int points = 0;
};
struct label {
    char c = 0;
};

TEST(command_buffer, nothing_happens_before_apply) {
    world w;
    const entity e = w.create();
    command_buffer cb;
    cb.emplace<health>(e, {3});
    cb.create();
    cb.destroy(e);
    EXPECT_EQ(cb.size(), 3u);
    EXPECT_TRUE(w.alive(e));
    EXPECT_FALSE(w.has<health>(e));
    EXPECT_EQ(w.entity_count(), 1u);
}

TEST(command_buffer, create_then_emplace_through_placeholder) {
    world w;
    command_buffer cb;
    const entity p = cb.create();
    EXPECT_TRUE(command_buffer::is_placeholder(p));
    cb.emplace<health>(p, {7});
    cb.emplace<label>(p, {'x'});
    cb.apply(w);
    ASSERT_EQ(cb.created().size(), 1u);
    const entity real = cb.created()[0];
    EXPECT_TRUE(w.alive(real));
    EXPECT_EQ(w.get<health>(real).points, 7);
    EXPECT_EQ(w.get<label>(real).c, 'x');
    EXPECT_TRUE(cb.empty());
}

TEST(command_buffer, applies_in_record_order) {
    world w;
    const entity e = w.create();
    command_buffer cb;
    cb.emplace<health>(e, {1});
    cb.emplace<health>(e, {2});
    cb.remove<label>(e);
    cb.emplace<label>(e, {'a'});
    cb.apply(w);
    EXPECT_EQ(w.get<health>(e).points, 2);
    EXPECT_TRUE(w.has<label>(e));
}

TEST(command_buffer, commands_after_destroy_are_skipped) {
    world w;
    const entity e = w.create();
    command_buffer cb;
    cb.destroy(e);
    cb.emplace<health>(e, {1});
    cb.apply(w);
    EXPECT_FALSE(w.alive(e));
    EXPECT_EQ(w.table<health>().size(), 0u);
}

TEST(command_buffer, append_preserves_order_and_renumbers_placeholders) {
    world w;
    command_buffer first, second;
    first.emplace<health>(first.create(), {1});
    second.emplace<health>(second.create(), {2});
    first.append(second);
    EXPECT_TRUE(second.empty());
    first.apply(w);
    ASSERT_EQ(first.created().size(), 2u);
    EXPECT_EQ(w.get<health>(first.created()[0]).points, 1);
    EXPECT_EQ(w.get<health>(first.created()[1]).points, 2);
}

TEST(command_buffer, same_recording_gives_same_handles) {
    auto record_and_apply = [] {
        world w;
        for (int i = 0; i < 3; ++i) w.destroy(w.create());
        command_buffer cb;
        for (int i = 0; i < 5; ++i) cb.emplace<health>(cb.create(), {i});
        cb.apply(w);
        return std::vector<entity>(cb.created().begin(), cb.created().end());
    };
    EXPECT_EQ(record_and_apply(), record_and_apply());
}

}  // namespace
}  // namespace sylva::ecs
