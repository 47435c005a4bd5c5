#include "ecs/component_table.h"

#include <gtest/gtest.h>

#include <vector>

namespace sylva::ecs {
namespace {

struct mass {
    float kg = 0.0f;
};

TEST(component_table, emplace_appends_densely_and_indexes_by_entity) {
    component_table<mass> t;
    t.emplace({7, 0}, {1.0f});
    t.emplace({3, 0}, {2.0f});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_FLOAT_EQ(t.data()[0].kg, 1.0f);
    EXPECT_FLOAT_EQ(t.data()[1].kg, 2.0f);
    EXPECT_EQ(t.index_of({3, 0}), 1u);
    EXPECT_EQ(t.entities()[0], (entity{7, 0}));
}

TEST(component_table, emplace_twice_overwrites_without_growing) {
    component_table<mass> t;
    t.emplace({1, 0}, {1.0f});
    const auto version = t.layout_version();
    t.emplace({1, 0}, {5.0f});
    EXPECT_EQ(t.size(), 1u);
    EXPECT_FLOAT_EQ(t.get({1, 0}).kg, 5.0f);
    EXPECT_EQ(t.layout_version(), version);  // a value write is not a layout change
}

TEST(component_table, contains_checks_generation) {
    component_table<mass> t;
    t.emplace({4, 2}, {});
    EXPECT_TRUE(t.contains({4, 2}));
    EXPECT_FALSE(t.contains({4, 1}));
    EXPECT_FALSE(t.contains({5, 2}));
    EXPECT_FALSE(t.contains(entity{}));
    EXPECT_EQ(t.try_get({4, 1}), nullptr);
    EXPECT_THROW(t.get({4, 1}), std::out_of_range);
}

TEST(component_table, swap_remove_keeps_table_dense_and_other_handles_valid) {
    component_table<mass> t;
    for (std::uint32_t i = 0; i < 5; ++i) t.emplace({i, 0}, {float(i)});
    EXPECT_TRUE(t.remove({1, 0}));
    ASSERT_EQ(t.size(), 4u);
    EXPECT_FALSE(t.contains({1, 0}));
    EXPECT_EQ(t.entities()[1], (entity{4, 0}));  // the last element filled the hole
    for (std::uint32_t i : {0u, 2u, 3u, 4u}) {
        ASSERT_TRUE(t.contains({i, 0}));
        EXPECT_FLOAT_EQ(t.get({i, 0}).kg, float(i));
    }
    EXPECT_FALSE(t.remove({1, 0}));
}

TEST(component_table, removing_last_element_needs_no_swap) {
    component_table<mass> t;
    t.emplace({0, 0}, {1.0f});
    t.emplace({1, 0}, {2.0f});
    EXPECT_TRUE(t.remove({1, 0}));
    EXPECT_EQ(t.size(), 1u);
    EXPECT_FLOAT_EQ(t.get({0, 0}).kg, 1.0f);
}

TEST(component_table, swap_dense_updates_sparse_index) {
    component_table<mass> t;
    t.emplace({0, 0}, {0.0f});
    t.emplace({1, 0}, {1.0f});
    t.swap_dense(0, 1);
    EXPECT_EQ(t.index_of({1, 0}), 0u);
    EXPECT_EQ(t.index_of({0, 0}), 1u);
    EXPECT_FLOAT_EQ(t.data()[0].kg, 1.0f);
}

TEST(component_table, clear_forgets_every_entity) {
    component_table<mass> t;
    t.emplace({2, 0}, {});
    t.clear();
    EXPECT_TRUE(t.empty());
    EXPECT_FALSE(t.contains({2, 0}));
    t.emplace({2, 0}, {3.0f});
    EXPECT_EQ(t.index_of({2, 0}), 0u);
}

}  // namespace
}  // namespace sylva::ecs
