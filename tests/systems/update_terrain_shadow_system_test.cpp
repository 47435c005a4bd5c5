// The terrain's shadow remade only when the sun moves (systems/update_terrain_shadow_system.h):
// a still sun leaves the revision alone, a moved one remakes the texels for its direction, and
// a scene without terrain has nothing to do.
#include "systems/update_terrain_shadow_system.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "ecs/executor.h"
#include "ecs/schedule.h"

namespace sylva {
namespace {

// A 3 m wall on the +x edge of a 5 x 5 field, 1 m apart.
terrain_shadow wall() {
    terrain_shadow shadow;
    shadow.resolution = 5;
    shadow.size_m = 4.0;
    shadow.heights.assign(25, 0.0f);
    for (std::size_t r = 0; r < 5; ++r) shadow.heights[r * 5 + 4] = 3.0f;
    return shadow;
}

TEST(update_terrain_shadow, remakes_the_shadow_only_when_the_sun_moves) {
    ecs::world world;
    sun s;
    s.direction = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));  // 45 degrees, due +x
    const ecs::entity light = world.create();
    world.emplace<sun>(light, s);
    world.set_resource(wall());
    ecs::schedule schedule;
    schedule.add<update_terrain_shadow_system>();
    schedule.build();
    ecs::executor executor(2);

    schedule.run(world, executor);
    const terrain_shadow& shadow = world.resource<terrain_shadow>();
    EXPECT_EQ(shadow.revision, 1u);
    // Column 3 (one metre from the wall): height 0, shadow depth 2 (the wall's 3 less 1 m at 45°).
    EXPECT_FLOAT_EQ(shadow.texels[2 * 3], 0.0f);
    EXPECT_NEAR(shadow.texels[2 * 3 + 1], 2.0f, 1e-5f);
    EXPECT_NEAR(shadow.deepest_m, 2.0f, 1e-5f);

    schedule.run(world, executor);
    EXPECT_EQ(shadow.revision, 1u) << "a still sun costs nothing";

    world.single<sun>().direction = glm::normalize(glm::vec3(2.0f, 1.0f, 0.0f));
    schedule.run(world, executor);
    EXPECT_EQ(shadow.revision, 2u);
    // tan = 1/2: one metre from the wall the shadow is 2.5 m deep.
    EXPECT_NEAR(shadow.texels[2 * 3 + 1], 2.5f, 1e-5f);
}

TEST(update_terrain_shadow, a_scene_without_terrain_has_nothing_to_do) {
    ecs::world world;
    world.emplace<sun>(world.create(), sun{});
    ecs::schedule schedule;
    schedule.add<update_terrain_shadow_system>();
    schedule.build();
    ecs::executor executor(1);
    schedule.run(world, executor);
    EXPECT_EQ(world.try_resource<terrain_shadow>(), nullptr);
}

}  // namespace
}  // namespace sylva
