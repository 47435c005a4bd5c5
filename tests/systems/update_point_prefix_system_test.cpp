// The point/line prefixes a plant gets for a known camera equal Eq. 1, Eq. 2 and the §5.3 blend
// computed by hand, and build_draw_list draws exactly those prefixes.
#include "systems/update_point_prefix_system.h"

#include <gtest/gtest.h>

#include <numbers>

#include "components/bounds.h"
#include "components/fade_alpha.h"
#include "ecs/executor.h"
#include "ecs/schedule.h"
#include "tests/systems/origin_camera.h"
#include "systems/build_draw_list_system.h"
#include "systems/cull_system.h"
#include "systems/select_representation_system.h"
#include "systems/update_camera_system.h"

namespace sylva {
namespace {

// One species of two parts: a point part (k = 10 triangles, 20 stratified points, A_p = 0.08)
// and a line part (k = 40 triangles, n_l = 10 lines, A_l = 0.18, l = 5, ε_l = 0.01), both
// centred on the plant's base. The camera looks down -z with a 90° field of view over 500
// pixels, so d' = 1 px is 0.004 on the image plane.
struct prefix_scene {
    ecs::world world;
    ecs::schedule schedule;

    // `dither` false: counts rounded down (points) or to nearest (splats), as the hand values.
    // The paper's opaque splats round counts; soft splats draw fractional prefixes.
    explicit prefix_scene(std::vector<double> distances, float point_importance = 1.0f,
                          bool dither = false, std::uint32_t first_seed = 0,
                          splat_style splats = splat_style::opaque) {
        species_library library;
        species_entry plant;
        plant.bounding_radius = 0.5f;
        plant.max_distance_m = 1e5f;
        plant.first_lod_part = 0;
        plant.lod_part_count = 2;
        library.species = {plant};
        library.meshes = {{10, representation::points, primitive_kind::triangles},
                          {20, representation::points, primitive_kind::points},
                          {40, representation::points, primitive_kind::triangles},
                          {10, representation::points, primitive_kind::lines}};
        lod_part_entry points;
        points.primitive = lod_primitive::points;
        points.importance = point_importance;
        points.area_m2 = 0.08f;
        points.triangle_count = 10;
        points.primitive_count = 20;
        points.mesh_triangles = 0;
        points.mesh_primitives = 1;
        for (std::uint32_t t = 0; t <= 10; ++t) library.points_after.push_back(2 * (10 - t));
        lod_part_entry lines;
        lines.primitive = lod_primitive::lines;
        lines.area_m2 = 0.18f;
        lines.triangle_count = 40;
        lines.primitive_count = 10;
        lines.line_length_m = 5.0f;
        lines.line_error_m = 0.01f;
        lines.mesh_triangles = 2;
        lines.mesh_primitives = 3;
        library.lod_parts = {points, lines};
        for (double z : distances) {
            const ecs::entity e = world.create();
            world.emplace<world_transform>(e, {{0.0, 0.0, -z}, 0.7f, 1.0f});
            world.emplace<bounds>(e, {0.5f, 0.0f});
            world.emplace<plant_instance>(e, {species_id{0}, 0, first_seed++});
            world.emplace<lod_state>(e);
            world.emplace<point_prefix>(e);
            world.emplace<fade_alpha>(e);
        }
        world.align<world_transform, bounds, plant_instance, lod_state, point_prefix, fade_alpha>();
        emplace_origin_camera(world);
        world.set_resource(std::move(library));
        world.set_resource(shadow_settings{1, 1024, 1.0f, 0.5f});
        world.set_resource(cascade_set{});
        world.set_resource(draw_list{});
        lod_policy policy;
        policy.mode = lod_policy::kind::points_lines;
        policy.points = {1.0f, 1.0f};
        policy.points.dither = dither;
        policy.points.splats = splats;
        policy.points.fog_weighted = false;  // the paper's d' everywhere, as the hand values
        world.set_resource(policy);
        world.set_resource(primitive_costs{});  // the paper's: a triangle costs three points
        world.set_resource(tile_point_sets{});
        world.set_resource(tile_point_draws{});
        schedule.add<cull_system>();
        schedule.add<select_representation_system>();
        schedule.add<update_point_prefix_system>();
        schedule.add<build_draw_list_system>();
        schedule.build();
    }

    const point_prefix& prefix(std::size_t i) const { return world.table<point_prefix>().data()[i]; }
};

TEST(update_point_prefix, prefixes_equal_eq1_eq2_and_the_blend_for_a_known_camera) {
    // p(r) = ½·0.08/r² / 0.004² = 2500/r² and q(r) = A_l/(r·l·d') = 0.18/(r·0.02) = 9/r; the
    // distances keep p and q·n_l away from whole numbers, where float rounding could go either way.
    prefix_scene scene({5.0, 9.5, 10.5, 13.0, 30.0});
    ecs::executor executor(2);
    scene.schedule.run(scene.world, executor);
    // r = 5: p = 100 >= 3k → all 10 triangles; q = 1.8 > 1 → all 40 line-part triangles.
    EXPECT_EQ(scene.prefix(0).triangles[0], 10u);
    EXPECT_EQ(scene.prefix(0).primitives[0], 0u);
    EXPECT_EQ(scene.prefix(0).triangles[1], 40u);
    EXPECT_EQ(scene.prefix(0).primitives[1], 0u);
    // r = 9.5: p = 27.70 → 7 triangles + the 6 points of the other 3; q = 0.947 → 9 lines.
    EXPECT_EQ(scene.prefix(1).triangles[0], 7u);
    EXPECT_EQ(scene.prefix(1).primitives[0], 6u);
    EXPECT_EQ(scene.prefix(1).triangles[1], 0u);
    EXPECT_EQ(scene.prefix(1).primitives[1], 9u);
    // r = 10.5: p = 22.68 → 2 triangles + 16 points; q = 0.857 → 9 lines.
    EXPECT_EQ(scene.prefix(2).triangles[0], 2u);
    EXPECT_EQ(scene.prefix(2).primitives[0], 16u);
    EXPECT_EQ(scene.prefix(2).primitives[1], 9u);
    // r = 13: p = 14.79 → the first 14 points; q = 0.692 → 7 lines.
    EXPECT_EQ(scene.prefix(3).triangles[0], 0u);
    EXPECT_EQ(scene.prefix(3).primitives[0], 14u);
    EXPECT_EQ(scene.prefix(3).primitives[1], 7u);
    // r = 30: p = 2.78 → 2 points; q = 0.3 → 3 lines.
    EXPECT_EQ(scene.prefix(4).primitives[0], 2u);
    EXPECT_EQ(scene.prefix(4).primitives[1], 3u);
}

TEST(update_point_prefix, dithered_counts_add_up_to_what_eq1_asks_of_many_plants) {
    // 1,000 plants at r = 30 (p = 2500/900 = 2.78 points each; q = 0.3 → 3 lines): rounded
    // down, every plant draws 2 points, 2,000 in all where Eq. 1 asks for 2,778; dithered,
    // each draws 2 or 3 and the total is within a few per cent of 2,778.
    prefix_scene plain(std::vector<double>(1000, 30.0));
    prefix_scene dithered(std::vector<double>(1000, 30.0), 1.0f, true, 12345);
    ecs::executor executor(2);
    plain.schedule.run(plain.world, executor);
    dithered.schedule.run(dithered.world, executor);
    std::uint32_t total_plain = 0, total_dithered = 0;
    for (std::size_t i = 0; i < 1000; ++i) {
        total_plain += plain.prefix(i).primitives[0];
        const std::uint32_t n = dithered.prefix(i).primitives[0];
        ASSERT_TRUE(n == 2u || n == 3u) << n;
        total_dithered += n;
        EXPECT_EQ(dithered.prefix(i).primitives[1], 3u);  // lines round to nearest either way
    }
    EXPECT_EQ(total_plain, 2000u);
    EXPECT_NEAR(double(total_dithered), 2777.8, 0.03 * 2777.8);
    // The same plant gets the same count every frame: nothing flickers.
    const point_prefix first = dithered.prefix(17);
    dithered.schedule.run(dithered.world, executor);
    EXPECT_EQ(dithered.prefix(17).primitives[0], first.primitives[0]);
}

// Soft splats: a points-only part draws ⌈p⌉ splats, the last faded out by ⌈p⌉ − p (in 1/255),
// so what is drawn grows continuously with p; blends and lines are as with opaque splats.
TEST(update_point_prefix, soft_splats_draw_a_fractional_prefix_whose_last_splat_fades) {
    prefix_scene scene({10.5, 13.0, 30.0, 60.0}, 1.0f, false, 0, splat_style::soft);
    ecs::executor executor(2);
    scene.schedule.run(scene.world, executor);
    // r = 10.5: p = 22.68 ≥ 2k blends as before: 2 triangles + 16 points, nothing faded.
    EXPECT_EQ(scene.prefix(0).triangles[0], 2u);
    EXPECT_EQ(scene.prefix(0).primitives[0], 16u);
    EXPECT_EQ(scene.prefix(0).last_fade[0], 0u);
    // r = 13: p = 2500/169 = 14.793 → 15 splats, the last faded by 0.207: 255 · 0.207 = 52.8.
    EXPECT_EQ(scene.prefix(1).primitives[0], 15u);
    EXPECT_EQ(scene.prefix(1).last_fade[0], 53u);
    // r = 30: p = 2.778 → 3 splats, faded by 0.222: 56.7.
    EXPECT_EQ(scene.prefix(2).primitives[0], 3u);
    EXPECT_EQ(scene.prefix(2).last_fade[0], 57u);
    // r = 60: p = 0.694 → 1 splat at opacity 0.694, faded by 0.306: 77.9.
    EXPECT_EQ(scene.prefix(3).primitives[0], 1u);
    EXPECT_EQ(scene.prefix(3).last_fade[0], 78u);
    EXPECT_EQ(scene.prefix(2).primitives[1], 3u);  // the line part rounds as before
    EXPECT_EQ(scene.prefix(2).last_fade[1], 0u);
    // build_draw_list hands the fractional length to the instance record: 3 − 57/255.
    const draw_list& list = scene.world.resource<draw_list>();
    int checked = 0;
    for (std::size_t i = 0; i < list.items.size(); ++i) {
        const sort_key_fields key = decode_sort_key(list.items[i].key);
        if (key.pass != render_pass::opaque || key.mesh != 1 || list.items[i].count != 3) continue;
        EXPECT_FLOAT_EQ(list.instances[i].fade, 3.0f - 57.0f / 255.0f);
        ++checked;
    }
    EXPECT_EQ(checked, 1);
}

TEST(update_point_prefix, importance_keeps_a_part_polygonal_longer_without_painting_it_over) {
    prefix_scene ordinary({9.5, 20.0});
    prefix_scene important({9.5, 20.0}, 2.0f);
    ecs::executor executor(1);
    ordinary.schedule.run(ordinary.world, executor);
    important.schedule.run(important.world, executor);
    // r = 9.5: p = 27.7 blends (7 triangles + 6 points); with importance 2, 2p = 55.4 >= 3k: all
    // 10 triangles.
    EXPECT_EQ(ordinary.prefix(0).triangles[0], 7u);
    EXPECT_EQ(important.prefix(0).triangles[0], 10u);
    EXPECT_EQ(important.prefix(0).primitives[0], 0u);
    // r = 20: p = 6.25 and 2p = 12.5 < 2k: points only for both, and as many as coverage needs.
    EXPECT_EQ(ordinary.prefix(1).primitives[0], 6u);
    EXPECT_EQ(important.prefix(1).primitives[0], 6u);
    // The line part (importance 1) is not affected.
    EXPECT_EQ(ordinary.prefix(0).primitives[1], important.prefix(0).primitives[1]);
}

TEST(update_point_prefix, build_draw_list_draws_exactly_the_prefixes) {
    prefix_scene scene({10.5});
    ecs::executor executor(1);
    scene.schedule.run(scene.world, executor);
    const draw_list& list = scene.world.resource<draw_list>();
    std::vector<std::pair<std::uint16_t, std::uint32_t>> opaque;
    for (const auto& item : list.items)
        if (decode_sort_key(item.key).pass == render_pass::opaque)
            opaque.emplace_back(decode_sort_key(item.key).mesh, item.count);
    // 2 triangles of mesh 0, 16 points of mesh 1, 9 lines of mesh 3; no line-part triangles.
    EXPECT_EQ(opaque, (std::vector<std::pair<std::uint16_t, std::uint32_t>>{{0, 2}, {1, 16}, {3, 9}}));
    EXPECT_EQ(list.triangles, 2u);
    EXPECT_EQ(list.points, 16u);
    EXPECT_EQ(list.lines, 9u);
    EXPECT_EQ(list.instances_by_representation[std::size_t(representation::points)], 1u);
}

// Deussen 2002 §6.1: a big plant split into two octree cells, one 5 m from the eye and one 30 m:
// the near cell is drawn as triangles, the far one as points, in the same frame.
TEST(update_point_prefix, octree_cells_of_one_plant_choose_independently) {
    prefix_scene scene({20.0});
    scene.world.table<world_transform>().data()[0].yaw = 0.0f;  // cell centres straight along -z
    species_library& library = scene.world.resource<species_library>();
    lod_part_entry near_part = library.lod_parts[0];
    near_part.center = {0.0f, 0.0f, 15.0f};  // the plant stands 20 m ahead: this part at 5 m
    lod_part_entry far_part = library.lod_parts[0];
    far_part.center = {0.0f, 0.0f, -10.0f};  // and this one at 30 m
    far_part.mesh_triangles = 2;
    far_part.mesh_primitives = 3;
    library.lod_parts = {near_part, far_part};
    library.cells = {{0, 1}, {1, 1}};
    library.species[0].lod_part_count = 0;  // a split plant's parts belong to its cells
    library.species[0].first_cell = 0;
    library.species[0].cell_count = 2;
    for (std::uint32_t c = 0; c < 2; ++c) {
        const ecs::entity e = scene.world.create();
        scene.world.emplace<octree_cell>(e, {0, c});
        scene.world.emplace<cell_prefix>(e);
    }
    ecs::executor executor(2);
    scene.schedule.run(scene.world, executor);
    const auto& cells = scene.world.table<cell_prefix>();
    ASSERT_EQ(cells.size(), 2u);
    // r = 5: p = 100 → all 10 triangles; r = 30: p = 2500/900 = 2.78 → 2 points.
    EXPECT_EQ(cells.data()[0].prefix.triangles[0], 10u);
    EXPECT_EQ(cells.data()[0].prefix.primitives[0], 0u);
    EXPECT_EQ(cells.data()[1].prefix.triangles[0], 0u);
    EXPECT_EQ(cells.data()[1].prefix.primitives[0], 2u);
    // The plant itself has no parts; its cells' items carry its instance.
    const draw_list& list = scene.world.resource<draw_list>();
    std::vector<std::pair<std::uint16_t, std::uint32_t>> opaque;
    for (const auto& item : list.items) {
        EXPECT_EQ(item.instance, 0u);
        if (decode_sort_key(item.key).pass == render_pass::opaque)
            opaque.emplace_back(decode_sort_key(item.key).mesh, item.count);
    }
    EXPECT_EQ(opaque, (std::vector<std::pair<std::uint16_t, std::uint32_t>>{{0, 10}, {3, 2}}));
}

TEST(update_point_prefix, shadow_casters_cover_exactly_the_leaf_area) {
    // A cascade sampled every τ = 0.048 m: p = ½·A/τ² with c_p = 1 (point_line_lod.h
    // k_shadow_sample_texels), = 0.04/0.002304 = 17.36 → the first 17 points (c_p = 1.3 would
    // ask for 22.57: 2 triangles and 16 points). Splats τ wide then cover 17·τ² = 0.039 m², the
    // part's ½·A = 0.04. The line part: ε_l = 0.01 < τ and lines 5/(2·10) = 0.25 m long > τ, so
    // Eq. 2's q = A_l/(l·τ) = 0.18/0.24 = 0.75 → 7.5 of its 10 lines, rounded to nearest: 8.
    prefix_scene scene({1.0});
    const species_library& library = scene.world.resource<species_library>();
    const point_prefix p = compute_shadow_prefix(library, parts_of(library.species[0]), 1.0f, 0.048,
                                                 primitive_costs{});
    EXPECT_EQ(p.triangles[0], 0u);
    EXPECT_EQ(p.primitives[0], 17u);
    EXPECT_EQ(p.triangles[1], 0u);
    EXPECT_EQ(p.primitives[1], 8u);
    EXPECT_EQ(p.splats[1], 0u);
    // Scale 2: four times the area, p = 69.4 >= 3k → all 10 triangles.
    EXPECT_EQ(
        compute_shadow_prefix(library, parts_of(library.species[0]), 2.0f, 0.048).triangles[0],
        10u);
}

TEST(update_point_prefix, fog_spaces_a_parts_points_by_what_the_fog_leaves_of_it) {
    // r = 13 with fog ρ = 0.02: d' grows by exp(ρ·r/2) = exp(0.13), so p = 14.793·exp(−0.26)
    // = 14.793·0.771052 = 11.41 → the first 11 points (14 without fog). The line part's lines
    // are 5/(2·13·10) = 0.0192 long on the image plane, longer than d' even grown (0.00456): they
    // stay lines, d' wide, and keep d' itself: q = 0.692 → 7 lines, as without fog.
    prefix_scene scene({13.0});
    const species_library& library = scene.world.resource<species_library>();
    const world_transform t{{0.0, 0.0, -13.0}, 0.7f, 1.0f};
    const glm::dvec3 eye{0.0};
    const point_prefix plain = compute_point_prefix(library, parts_of(library.species[0]), t, eye,
                                                    0.004, 1.0, primitive_costs{});
    const point_prefix fogged =
        compute_point_prefix(library, parts_of(library.species[0]), t, eye, 0.004, 1.0,
                             primitive_costs{}, std::nullopt, false, 0.02);
    EXPECT_EQ(plain.primitives[0], 14u);
    EXPECT_EQ(fogged.primitives[0], 11u);
    EXPECT_EQ(plain.primitives[1], 7u);
    EXPECT_EQ(fogged.primitives[1], 7u);
    EXPECT_EQ(fogged.splats[1], 0u);
}

TEST(update_point_prefix, the_part_centre_follows_the_instance_yaw_and_scale) {
    lod_part_entry part;
    part.center = {1.0f, 2.0f, 0.0f};
    const world_transform t{{10.0, 0.0, 0.0}, float(std::numbers::pi / 2.0), 2.0f};
    // yaw 90°: x' = c·x + s·z = 0, z' = −s·x + c·z = −2 (scaled x = 2).
    const glm::dvec3 c = part_world_center(part, t);
    EXPECT_NEAR(c.x, 10.0, 1e-6);
    EXPECT_NEAR(c.y, 4.0, 1e-6);
    EXPECT_NEAR(c.z, -2.0, 1e-6);
}

}  // namespace
}  // namespace sylva
