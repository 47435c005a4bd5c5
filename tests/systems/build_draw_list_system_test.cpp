#include "systems/build_draw_list_system.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "components/point_prefix.h"
#include "ecs/executor.h"
#include "ecs/schedule.h"
#include "systems/cull_system.h"
#include "systems/select_representation_system.h"
#include "systems/update_camera_system.h"

namespace sylva {
namespace {

// Three plants straight ahead at 10 m (full mesh), 100 m (reduced) and 300 m (far); two
// cascades whose light boxes cover everything.
struct three_plants {
    ecs::world world;
    ecs::schedule schedule;

    explicit three_plants(std::vector<double> zs = {-10.0, -100.0, -300.0}, double camera_y = 5.0) {
        species_library library;
        species_entry oak;
        oak.mesh_full = 1;
        oak.mesh_reduced = 2;
        oak.mesh_far = 3;
        oak.mesh_billboard = 4;
        oak.mesh_cloud = 5;
        oak.reduced_distance_m = 50.0f;
        oak.far_distance_m = 200.0f;
        oak.bounding_radius = 5.0f;
        oak.center_height = 5.0f;
        oak.texture_layer = 0.0f;
        library.species = {oak};
        library.meshes = {{100, representation::none}, {6000, representation::mesh_full},
                          {800, representation::mesh_reduced}, {150, representation::mesh_far},
                          {4, representation::crossed_billboard}, {400, representation::billboard_cloud}};
        for (double z : zs) {
            const ecs::entity e = world.create();
            world.emplace<world_transform>(e, {{0.0, 0.0, z}, 0.0f, 1.0f});
            world.emplace<bounds>(e, {5.0f, 5.0f});
            world.emplace<plant_instance>(e, {species_id{0}, 0, 0});
            world.emplace<lod_state>(e);
            world.emplace<point_prefix>(e);
            world.emplace<fade_alpha>(e);
        }
        world.align<world_transform, bounds, plant_instance, lod_state, point_prefix, fade_alpha>();
        camera cam;
        cam.position = {0.0, camera_y, 0.0};
        cam.far_plane = 1000.0f;
        derive_camera_matrices(cam);
        world.emplace<camera>(world.create(), cam);
        cascade_set cascades;
        cascades.count = 2;
        const glm::mat4 everything = glm::ortho(-1000.0f, 1000.0f, -1000.0f, 1000.0f, -1000.0f, 1000.0f);
        cascades.light_view_projection = {everything, everything, everything, everything};
        world.set_resource(std::move(library));
        world.set_resource(shadow_settings{2, 1024, 1000.0f, 0.5f});
        world.set_resource(cascades);
        world.set_resource(draw_list{});
        world.set_resource(lod_policy{});
        world.set_resource(primitive_costs{});
        world.set_resource(tile_point_sets{});
        world.set_resource(tile_point_draws{});
        schedule.add<cull_system>();
        schedule.add<select_representation_system>();
        schedule.add<build_draw_list_system>();
        schedule.build();
    }
};

std::vector<std::uint16_t> meshes_in(const draw_list& list, render_pass pass) {
    std::vector<std::uint16_t> meshes;
    for (const auto& item : list.items)
        if (decode_sort_key(item.key).pass == pass) meshes.push_back(decode_sort_key(item.key).mesh);
    return meshes;
}

TEST(build_draw_list, each_cascade_draws_one_mesh_level_coarser_than_the_one_before) {
    three_plants scene;
    ecs::executor executor(2);
    scene.schedule.run(scene.world, executor);
    const draw_list& list = scene.world.resource<draw_list>();
    EXPECT_EQ(meshes_in(list, render_pass::opaque), (std::vector<std::uint16_t>{1, 2, 3}));
    EXPECT_EQ(meshes_in(list, render_pass::shadow_cascade_0), (std::vector<std::uint16_t>{1, 2, 3}));
    EXPECT_EQ(meshes_in(list, render_pass::shadow_cascade_1), (std::vector<std::uint16_t>{2, 3, 3}));
    EXPECT_TRUE(meshes_in(list, render_pass::shadow_cascade_2).empty());
}

// A ladder may name what a rung casts its shadow as (ladder::shadow): the near plant, drawn as
// its full mesh, casts as its billboard cloud in every cascade; the others as before.
TEST(build_draw_list, a_rung_casts_as_the_rung_its_ladder_names) {
    three_plants scene;
    ladder l;
    l.count = 4;
    l.rungs = {representation::mesh_full, representation::mesh_reduced, representation::mesh_far,
               representation::billboard_cloud};
    l.shadow[0] = representation::billboard_cloud;
    scene.world.resource<lod_policy>().ladders = {l};
    ecs::executor executor(2);
    scene.schedule.run(scene.world, executor);
    const draw_list& list = scene.world.resource<draw_list>();
    EXPECT_EQ(meshes_in(list, render_pass::opaque), (std::vector<std::uint16_t>{1, 2, 3}));
    EXPECT_EQ(meshes_in(list, render_pass::shadow_cascade_0), (std::vector<std::uint16_t>{2, 3, 5}));
    EXPECT_EQ(meshes_in(list, render_pass::shadow_cascade_1), (std::vector<std::uint16_t>{3, 3, 5}));
}

// A facing billboard turns to the eye, so it casts its crossed billboard (lod/ladder.h
// caster_of), whose shadow does not turn with the eye, unless its ladder names another caster.
TEST(build_draw_list, a_facing_billboard_casts_its_crossed_billboard) {
    three_plants scene;
    species_library& library = scene.world.resource<species_library>();
    library.species[0].mesh_facing = 6;
    library.meshes.push_back({2, representation::facing_billboard});
    ladder l;
    l.count = 1;
    l.rungs[0] = representation::facing_billboard;
    lod_policy& policy = scene.world.resource<lod_policy>();
    policy.mode = lod_policy::kind::ladder;
    policy.ladders = {l};
    scene.world.set_resource(rung_budget{});  // none: by projected size
    scene.world.set_resource(seen_pixels{});
    ecs::executor executor(2);
    scene.schedule.run(scene.world, executor);
    EXPECT_EQ(meshes_in(scene.world.resource<draw_list>(), render_pass::opaque), (std::vector<std::uint16_t>{6, 6, 6}));
    EXPECT_EQ(meshes_in(scene.world.resource<draw_list>(), render_pass::shadow_cascade_0),
              (std::vector<std::uint16_t>{4, 4, 4}));
    EXPECT_EQ(meshes_in(scene.world.resource<draw_list>(), render_pass::shadow_cascade_1),
              (std::vector<std::uint16_t>{4, 4, 4}));
    // Named, the ladder's caster wins.
    policy.ladders[0].shadow[0] = representation::facing_billboard;
    scene.schedule.run(scene.world, executor);
    EXPECT_EQ(meshes_in(scene.world.resource<draw_list>(), render_pass::shadow_cascade_0),
              (std::vector<std::uint16_t>{6, 6, 6}));
}

TEST(build_draw_list, a_cascade_without_receivers_gets_no_casters) {
    three_plants scene;
    scene.world.resource<cascade_set>().holds_receivers[0] = false;  // its slice is air
    ecs::executor executor(2);
    scene.schedule.run(scene.world, executor);
    const draw_list& list = scene.world.resource<draw_list>();
    EXPECT_TRUE(meshes_in(list, render_pass::shadow_cascade_0).empty());
    EXPECT_EQ(meshes_in(list, render_pass::shadow_cascade_1),
              (std::vector<std::uint16_t>{2, 3, 3}));
}

TEST(build_draw_list, items_are_sorted_and_batched_with_camera_relative_instances) {
    three_plants scene;
    ecs::executor executor(1);
    scene.schedule.run(scene.world, executor);
    const draw_list& list = scene.world.resource<draw_list>();
    ASSERT_EQ(list.items.size(), 9u);
    for (std::size_t i = 1; i < list.items.size(); ++i) EXPECT_LE(list.items[i - 1].key, list.items[i].key);
    // cascade 0: 3 meshes, cascade 1: meshes 2 and 3 (two plants share the far mesh), opaque: 3.
    ASSERT_EQ(list.batches.size(), 8u);
    EXPECT_EQ(list.batches[4].mesh, 3);
    EXPECT_EQ(list.batches[4].instance_count, 2u);
    EXPECT_EQ(list.triangles, 6000u + 800u + 150u);
    EXPECT_EQ(list.instances_by_representation[std::size_t(representation::mesh_far)], 1u);
    // The last opaque batch is the far mesh: the plant 300 m ahead, relative to the camera at y = 5.
    const auto& last = list.batches.back();
    EXPECT_EQ(list.instances[last.first_instance].position, glm::vec3(0.0f, -5.0f, -300.0f));
}

TEST(build_draw_list, plants_behind_the_camera_are_not_drawn_but_may_cast_shadows) {
    three_plants scene;
    scene.world.single<camera>().forward = {0.0f, 0.0f, 1.0f};  // looking away
    derive_camera_matrices(scene.world.single<camera>());
    ecs::executor executor(2);
    scene.schedule.run(scene.world, executor);
    const draw_list& list = scene.world.resource<draw_list>();
    EXPECT_TRUE(meshes_in(list, render_pass::opaque).empty());
    EXPECT_EQ(meshes_in(list, render_pass::shadow_cascade_0).size(), 3u);
}

// Behrendt 2005 §2.3 under the billboard-cloud policy: during a band the visible plant adds its
// partner in the opaque pass only (marked, with the partner's fade in its instance record);
// shadows come from the primaries alone.
TEST(build_draw_list, billboard_cloud_bands_add_faded_partners_to_the_view_only) {
    // At 10 m polygons; 33 m the cloud with the full mesh fading out (1/3); 100 m the cloud;
    // 176 m the cloud with the crossed billboard fading in (0.2); 300 m the crossed billboard.
    three_plants scene({-10.0, -33.0, -100.0, -176.0, -300.0}, 0.0);
    lod_policy policy;
    policy.mode = lod_policy::kind::billboard_clouds;
    scene.world.set_resource(policy);
    ecs::executor executor(2);
    scene.schedule.run(scene.world, executor);
    const draw_list& list = scene.world.resource<draw_list>();
    // The partners (the full mesh fading out, the crossed billboard fading in) dissolve by the
    // screen door: their items are marked faded and sort after the plants drawn whole, whose
    // programs have no dissolve (a cloud partner, which thins by its own threshold, is not).
    EXPECT_EQ(meshes_in(list, render_pass::opaque), (std::vector<std::uint16_t>{1, 4, 5, 5, 5, 1, 4}));
    EXPECT_EQ(meshes_in(list, render_pass::shadow_cascade_0), (std::vector<std::uint16_t>{1, 4, 5, 5, 5}));
    std::vector<std::pair<std::uint16_t, float>> partners;
    for (std::size_t i = 0; i < list.items.size(); ++i) {
        const bool partner = (list.items[i].instance & k_partner_item_bit) != 0;
        const sort_key_fields key = decode_sort_key(list.items[i].key);
        EXPECT_EQ(key.faded, partner) << "item " << i;
        if (partner) partners.emplace_back(key.mesh, list.instances[i].fade);
        else EXPECT_EQ(list.instances[i].fade, 1.0f);
    }
    ASSERT_EQ(partners.size(), 2u);
    EXPECT_EQ(partners[0].first, 1);
    EXPECT_NEAR(partners[0].second, 1.0f / 3.0f, 1e-4f);
    EXPECT_EQ(partners[1].first, 4);
    EXPECT_NEAR(partners[1].second, 0.2f, 1e-4f);
    const auto& lod = scene.world.table<lod_state>();
    EXPECT_EQ(lod.data()[1].current, representation::billboard_cloud);
    EXPECT_EQ(lod.data()[4].current, representation::crossed_billboard);
}

}  // namespace
}  // namespace sylva
