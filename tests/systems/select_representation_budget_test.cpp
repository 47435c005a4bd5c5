// The budget solver in the frame (systems/select_representation_system.cpp), by hand: with a
// ladder ending in the shell (Behrendt 2005 §3.3 end) the shell takes over by its own fade, as by
// size, and its plants are neither a choice nor a cost of the solver's; a plant's shadow is
// costed at the cascade it casts into, and not at all when it casts into none; a gain (error per
// µs a dearer rung must buy) holds λ from below, alone or under a budget.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <span>
#include <tuple>
#include <vector>

#include "ecs/executor.h"
#include "ecs/schedule.h"
#include "systems/select_representation_system.h"
#include "tests/systems/origin_camera.h"

namespace sylva {
namespace {

// One species of radius 1 m, its ladder full mesh, crossed billboard below 40 px, shell below
// 10 px; the shell fades in from 200 m (0) to 300 m (1), set by hand here (update_shells
// derives it from the ladder). The tables: the full mesh no error for 100 µs, the crossed
// billboard an error of 1,000 for 1 µs, at every size; no shadow cost (no plant casts).
struct shell_budget_scene {
    ecs::world world;
    ecs::schedule schedule;

    shell_budget_scene(const std::vector<double>& distances, double budget_us) {
        species_library library;
        species_entry plant;
        plant.bounding_radius = 1.0f;
        library.species = {plant};
        for (const double z : distances) {
            const ecs::entity e = world.create();
            world.emplace<world_transform>(e, {{0.0, 0.0, -z}, 0.0f, 1.0f});
            world.emplace<bounds>(e, {1.0f, 0.0f});
            world.emplace<plant_instance>(e, {species_id{0}, 0, 7});
            world.emplace<lod_state>(e, {representation::none, representation::none, 1, 0});  // seen, not casting
            world.emplace<fade_alpha>(e);
        }
        emplace_origin_camera(world);
        lod_policy policy;
        policy.mode = lod_policy::kind::ladder;
        ladder l;
        l.count = 3;
        l.rungs = {representation::mesh_full, representation::crossed_billboard, representation::shell};
        l.below_px = {0.0f, 40.0f, 10.0f};
        l.band = {0.0f, 0.25f, 0.5f};
        policy.ladders = {l};
        shell_view shells;
        shells.active = true;
        shells.fade_start_m = 200.0f;
        shells.fade_end_m = 300.0f;
        rung_budget budget;
        species_rung_tables tables;
        rung_table mesh, crossed;
        mesh.rung = representation::mesh_full;
        mesh.cost_us.fill(100.0f);
        crossed.rung = representation::crossed_billboard;
        crossed.error.fill(1000.0f);
        crossed.cost_us.fill(1.0f);
        tables.rungs = {mesh, crossed};
        tables.plant_pixels.fill(50.0f);
        budget.tables = {tables};
        budget.plant_budget_us = budget_us;
        world.set_resource(std::move(library));
        world.set_resource(std::move(policy));
        world.set_resource(std::move(shells));
        world.set_resource(std::move(budget));
        world.set_resource(seen_pixels{});
        world.set_resource(cascade_set{});  // no shadows: no plant casts
        schedule.add<select_representation_system>();
        schedule.build();
    }

    void run() {
        ecs::executor executor(2);
        schedule.run(world, executor);
    }
    const lod_state& lod(std::size_t i) const { return world.table<lod_state>().data()[i]; }
    const fade_alpha& fade(std::size_t i) const { return world.table<fade_alpha>().data()[i]; }
    void move_to(std::size_t i, double z) { world.table<world_transform>().data()[i].position.z = -z; }
    void place(std::size_t i, glm::dvec3 at) { world.table<world_transform>().data()[i].position = at; }
};

TEST(select_representation_budget, beyond_the_band_the_shell_near_the_solver_between_a_handover) {
    // 100 m: before the band (fade 0), the solver's choice whole. 275 m: fade 0.75, the shell
    // with the solver's choice as partner at 2(1 − 0.75) = 0.5. 350 m: the shell's alone.
    // A budget of 250 µs holds the two plants the solver weighs on full meshes (200 µs); were
    // the shell's plant counted too (300 µs), one of them would go to its crossed billboard.
    shell_budget_scene scene({100.0, 275.0, 350.0}, 250.0);
    scene.run();
    EXPECT_EQ(scene.lod(0).current, representation::mesh_full);
    EXPECT_EQ(scene.fade(0).partner, representation::none);
    EXPECT_EQ(scene.lod(1).current, representation::shell);
    EXPECT_EQ(scene.fade(1).partner, representation::mesh_full);
    EXPECT_FLOAT_EQ(scene.fade(1).value, 0.5f);
    EXPECT_EQ(scene.lod(2).current, representation::shell);
    EXPECT_EQ(scene.fade(2).partner, representation::none);
    const rung_budget& budget = scene.world.resource<rung_budget>();
    EXPECT_DOUBLE_EQ(budget.predicted_us, 200.0);
    EXPECT_DOUBLE_EQ(budget.lambda, 0.0);
}

TEST(select_representation_budget, a_plant_leaving_the_band_keeps_its_rung_without_a_dissolve) {
    // The plant in the band last frame drew its full mesh as the shell's partner: walked up to
    // (150 m, before the band) it is that full mesh whole, nothing dissolving; walked back into
    // the band's near half (fade 0.3) too, the shell showing through by its own fade.
    shell_budget_scene scene({275.0}, 250.0);
    scene.run();
    ASSERT_EQ(scene.lod(0).current, representation::shell);
    scene.move_to(0, 150.0);
    scene.run();
    EXPECT_EQ(scene.lod(0).current, representation::mesh_full);
    EXPECT_EQ(scene.fade(0).partner, representation::none) << "the plant's rung did not change: no dissolve";
    scene.move_to(0, 230.0);
    scene.run();
    EXPECT_EQ(scene.lod(0).current, representation::mesh_full);
    EXPECT_EQ(scene.fade(0).partner, representation::none);
    scene.move_to(0, 290.0);  // fade 0.9: partner at 0.2
    scene.run();
    EXPECT_EQ(scene.lod(0).current, representation::shell);
    EXPECT_EQ(scene.fade(0).partner, representation::mesh_full);
    EXPECT_NEAR(scene.fade(0).value, 0.2f, 1e-6f);
}

// In the far half of the shell's band a plant's rung is the shell's partner, fading out: it keeps
// the rung it came with even when the budget falls, and the budget counts it. Both plants on full
// meshes under 250 µs; at 50 µs the plant at 100 m goes to its crossed billboard (1 µs), the one
// at 275 m keeps its full mesh (100 µs): 101 µs predicted, over the budget by what it holds.
TEST(select_representation_budget, a_plant_handing_over_to_the_shell_keeps_its_rung) {
    shell_budget_scene scene({100.0, 275.0}, 250.0);
    scene.run();
    ASSERT_EQ(scene.lod(0).current, representation::mesh_full);
    ASSERT_EQ(scene.fade(1).partner, representation::mesh_full);
    scene.world.resource<rung_budget>().plant_budget_us = 50.0;
    scene.run();
    EXPECT_EQ(scene.lod(0).current, representation::crossed_billboard);
    EXPECT_EQ(scene.lod(1).current, representation::shell);
    EXPECT_EQ(scene.fade(1).partner, representation::mesh_full) << "held through the handover";
    EXPECT_FLOAT_EQ(scene.fade(1).value, 0.5f);
    EXPECT_DOUBLE_EQ(scene.world.resource<rung_budget>().predicted_us, 101.0);
}

// Two plants out of view but in shadow range, 50 m ahead: one inside the only cascade's box
// (±100 m across, 0.1 m texels), one 150 m to the side, outside it. The tables measured the
// full mesh's shadow at 300 µs (200 of it fragments) and the crossed billboard's at 30 µs (20),
// both at 0.05 m texels. Showing nothing, each takes its cheapest shadow: inside the box the
// billboard's, its fragments a quarter as many at twice the texel, 10 + 20/4 = 15 µs; outside,
// casting into no cascade, nothing.
TEST(select_representation_budget, a_shadow_is_costed_at_its_cascade_and_not_where_none_holds_it) {
    shell_budget_scene scene({50.0, 50.0}, 1000.0);
    scene.place(1, {150.0, 0.0, -50.0});
    for (lod_state& lod : std::span(scene.world.table<lod_state>().data(), 2)) lod = {representation::none, representation::none, 0, 1};
    rung_budget& budget = scene.world.resource<rung_budget>();
    for (rung_table& t : budget.tables[0].rungs) {
        const bool mesh = t.rung == representation::mesh_full;
        t.shadow_cost_us.fill(mesh ? 300.0f : 30.0f);
        t.shadow_fragment_cost_us.fill(mesh ? 200.0f : 20.0f);
        t.shadow_texel_m.fill(0.05f);
    }
    cascade_set cascades;
    cascades.count = 1;
    cascades.light_view_projection[0] = glm::ortho(-100.0f, 100.0f, -100.0f, 100.0f, -1000.0f, 1000.0f);
    cascades.texel_world_size[0] = 0.1f;
    scene.world.set_resource(cascades);
    scene.run();
    EXPECT_EQ(scene.lod(0).current, representation::crossed_billboard);
    EXPECT_DOUBLE_EQ(scene.world.resource<rung_budget>().predicted_us, 15.0);
}

// The scene's tables by hand: the full mesh puts right an error of 1,000 for 99 µs more than the
// crossed billboard, 1000 / 99 = 10.10 per µs (10,101 pixels' worth a ms).
TEST(select_representation_budget,
     a_gain_alone_buys_a_dearer_rung_only_where_it_is_worth_the_gain) {
    for (const auto& [gain, rung, cost] :
         {std::tuple{10.0, representation::mesh_full, 300.0},
          std::tuple{10.2, representation::crossed_billboard, 3.0}}) {
        shell_budget_scene scene({50.0, 100.0, 150.0}, 0.0);  // no budget
        scene.world.resource<rung_budget>().gain_per_us = gain;
        scene.run();
        for (std::size_t i = 0; i < 3; ++i)
            EXPECT_EQ(scene.lod(i).current, rung) << "gain " << gain << ", plant " << i;
        const rung_budget& budget = scene.world.resource<rung_budget>();
        EXPECT_DOUBLE_EQ(budget.predicted_us, cost)
            << "gain " << gain;  // no budget holds it: each plant alike
        EXPECT_DOUBLE_EQ(budget.lambda, gain);
    }
}

TEST(select_representation_budget, under_a_budget_a_gain_is_a_floor_on_lambda) {
    // The higher λ rules. A budget of 1,000 µs holds three meshes (λ 0): a gain below the
    // breakpoint keeps them, one above it puts every plant on its crossed billboard. A budget of
    // 5 µs needs every plant there, whatever the gain below the breakpoint says.
    for (const auto& [budget_us, gain, cost] :
         {std::tuple{1000.0, 1.0, 300.0}, std::tuple{1000.0, 10.2, 3.0},
          std::tuple{5.0, 1.0, 3.0}}) {
        shell_budget_scene scene({50.0, 100.0, 150.0}, budget_us);
        scene.world.resource<rung_budget>().gain_per_us = gain;
        scene.run();
        EXPECT_DOUBLE_EQ(scene.world.resource<rung_budget>().predicted_us, cost)
            << "budget " << budget_us << " µs, gain " << gain;
    }
}

}  // namespace
}  // namespace sylva
