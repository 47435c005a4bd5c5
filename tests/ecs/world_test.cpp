#include "ecs/world.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace sylva::ecs {
namespace {

struct camera {
    float fov = 1.0f;
};
struct never_used {
    int x = 0;
};
struct species_library {
    std::vector<std::string> names;  // resources may own containers
};

TEST(world, emplace_get_remove_round_trip) {
    world w;
    const entity e = w.create();
    w.emplace<camera>(e, {2.0f});
    EXPECT_TRUE(w.has<camera>(e));
    EXPECT_FLOAT_EQ(w.get<camera>(e).fov, 2.0f);
    w.remove<camera>(e);
    EXPECT_FALSE(w.has<camera>(e));
    EXPECT_EQ(w.try_get<camera>(e), nullptr);
}

TEST(world, destroy_removes_entity_from_every_table) {
    world w;
    const entity e = w.create();
    w.emplace<camera>(e);
    w.emplace<never_used>(e);
    w.destroy(e);
    EXPECT_EQ(w.table<camera>().size(), 0u);
    EXPECT_EQ(w.table<never_used>().size(), 0u);
}

TEST(world, const_table_of_unused_type_is_empty_and_creates_nothing) {
    world w;
    const world& cw = w;
    EXPECT_EQ(cw.table<never_used>().size(), 0u);
    EXPECT_FALSE(cw.has<never_used>(w.create()));
}

TEST(world, single_returns_the_only_instance) {
    world w;
    const entity e = w.create();
    w.emplace<camera>(e, {3.0f});
    EXPECT_FLOAT_EQ(w.single<camera>().fov, 3.0f);
    EXPECT_EQ(w.single_entity<camera>(), e);
    w.single<camera>().fov = 4.0f;
    EXPECT_FLOAT_EQ(std::as_const(w).single<camera>().fov, 4.0f);
}

TEST(world, single_throws_for_zero_or_two_instances) {
    world w;
    EXPECT_THROW(w.single<camera>(), std::logic_error);
    w.emplace<camera>(w.create());
    w.emplace<camera>(w.create());
    EXPECT_THROW(std::as_const(w).single<camera>(), std::logic_error);
}

TEST(world, resource_may_own_containers_and_keeps_address_on_reset) {
    world w;
    EXPECT_EQ(w.try_resource<species_library>(), nullptr);
    EXPECT_THROW(w.resource<species_library>(), std::logic_error);
    species_library& lib = w.set_resource(species_library{{"birch", "fern"}});
    EXPECT_EQ(w.resource<species_library>().names.size(), 2u);
    w.set_resource(species_library{{"oak"}});
    EXPECT_EQ(&lib, &w.resource<species_library>());
    EXPECT_EQ(std::as_const(w).resource<species_library>().names.front(), "oak");
    EXPECT_TRUE(w.has_resource<species_library>());
}

TEST(world, frame_index_round_trips) {
    world w;
    EXPECT_EQ(w.frame_index(), 0u);
    w.set_frame_index(42);
    EXPECT_EQ(w.frame_index(), 42u);
}

TEST(world, move_keeps_entities_components_and_resources) {
    world a;
    const entity e = a.create();
    a.emplace<camera>(e, {5.0f});
    a.set_resource(species_library{{"x"}});
    world b(std::move(a));
    EXPECT_TRUE(b.alive(e));
    EXPECT_FLOAT_EQ(b.get<camera>(e).fov, 5.0f);
    EXPECT_EQ(b.resource<species_library>().names.size(), 1u);
}

}  // namespace
}  // namespace sylva::ecs
