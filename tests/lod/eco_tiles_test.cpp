// Eco tiles (Deussen 2002 §6.2): the quadtree subdivision invariants, and hierarchical culling
// that gives every plant exactly the flat result while skipping culled tiles' plants.
#include "lod/eco_tiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <numeric>

#include "components/tile.h"
#include "components/tile_visibility.h"
#include "ecs/executor.h"
#include "ecs/schedule.h"
#include "models/terrain/placement.h"
#include "models/random.h"
#include "systems/cull_system.h"
#include "systems/update_camera_system.h"

namespace sylva {
namespace {

std::vector<glm::dvec2> random_points(std::size_t n, std::array<double, 4> area,
                                      std::uint64_t seed) {
    rng random(seed);
    std::vector<glm::dvec2> points(n);
    for (auto& p : points) {
        p.x = random.uniform_double(area[0], area[2]);
        p.y = random.uniform_double(area[1], area[3]);
    }
    return points;
}

bool inside(glm::dvec2 p, const eco_tile_node& n) {
    return p.x >= n.min.x && p.x <= n.min.x + n.size && p.y >= n.min.y && p.y <= n.min.y + n.size;
}

TEST(build_eco_tiles, leaves_hold_at_most_n_contiguous_plants_covering_each_once) {
    const std::array<double, 4> area{-100.0, -50.0, 100.0, 150.0};
    auto points = random_points(20000, area, 3);
    // A clump denser than elsewhere, so the tree is uneven.
    for (std::size_t i = 0; i < 3000; ++i)
        points[i] = glm::dvec2(10.0, 20.0) + (points[i] - glm::dvec2(0.0, 50.0)) * 0.01;
    const std::uint32_t n = 64;
    const eco_tile_tree tree = build_eco_tiles(points, area, n);
    ASSERT_EQ(tree.order.size(), points.size());
    std::vector<std::uint32_t> sorted = tree.order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::uint32_t> identity(points.size());
    std::iota(identity.begin(), identity.end(), 0u);
    EXPECT_EQ(sorted, identity);  // a permutation: every plant exactly once

    const eco_tile_node& root = tree.nodes[0];
    EXPECT_EQ(root.parent, k_no_eco_tile);
    EXPECT_EQ(root.first_plant, 0u);
    EXPECT_EQ(root.plant_count, points.size());
    std::uint32_t next_slot = 0;  // leaves in preorder tile the slots left to right
    std::size_t leaves = 0;
    for (std::uint32_t i = 0; i < tree.nodes.size(); ++i) {
        const eco_tile_node& node = tree.nodes[i];
        for (std::uint32_t s = node.first_plant; s < node.first_plant + node.plant_count; ++s)
            ASSERT_TRUE(inside(points[tree.order[s]], node)) << "node " << i << " slot " << s;
        if (node.is_leaf()) {
            ++leaves;
            EXPECT_LE(node.plant_count, n);
            EXPECT_EQ(node.first_plant, next_slot);
            next_slot += node.plant_count;
            continue;
        }
        EXPECT_GT(node.plant_count, n);
        std::uint32_t first = node.first_plant;
        for (std::uint32_t q = 0; q < 4; ++q) {
            const eco_tile_node& child = tree.nodes[node.children[q]];
            EXPECT_EQ(child.parent, i);
            EXPECT_EQ(child.depth, node.depth + 1);
            EXPECT_EQ(child.size, node.size * 0.5);
            EXPECT_EQ(child.first_plant, first);  // children split the parent's range in order
            first += child.plant_count;
        }
        EXPECT_EQ(first, node.first_plant + node.plant_count);
    }
    EXPECT_EQ(next_slot, points.size());
    EXPECT_GT(leaves, points.size() / n);
    // Deterministic.
    const eco_tile_tree again = build_eco_tiles(points, area, n);
    EXPECT_EQ(again.order, tree.order);
    EXPECT_EQ(again.nodes.size(), tree.nodes.size());
}

TEST(build_eco_tiles, few_plants_give_one_root_and_coincident_plants_stop_at_max_depth) {
    const std::array<double, 4> area{0.0, 0.0, 10.0, 10.0};
    const auto few = random_points(5, area, 1);
    const eco_tile_tree one = build_eco_tiles(few, area, 5);
    EXPECT_EQ(one.nodes.size(), 1u);
    EXPECT_TRUE(one.nodes[0].is_leaf());
    const std::vector<glm::dvec2> same(10, glm::dvec2(3.0, 3.0));
    const eco_tile_tree deep = build_eco_tiles(same, area, 1);
    const auto max_depth =
        std::max_element(deep.nodes.begin(), deep.nodes.end(), [](const auto& a, const auto& b) {
            return a.depth < b.depth;
        })->depth;
    EXPECT_EQ(max_depth, k_max_eco_tile_depth);
    EXPECT_THROW(build_eco_tiles(few, area, 0), std::invalid_argument);
    // A plant outside the area grows the root to hold it.
    const std::vector<glm::dvec2> outside{{20.0, -5.0}};
    const eco_tile_node root = build_eco_tiles(outside, area, 4).nodes[0];
    EXPECT_TRUE(inside(outside[0], root));
}

// --- a small world: terrain, plants in eco tile order, a camera --------------------------

constexpr float k_radius = 3.0f;
constexpr float k_center_height = 4.0f;

struct test_scene {
    ecs::world world;
    heightfield terrain;
    std::vector<placement> plants;  // in input (placement) order
    eco_tile_tree tree;
    std::vector<ecs::entity> tiles;
    std::vector<ecs::entity> plant_entities;  // dense order
};

void add_plant(ecs::world& world, const heightfield& terrain, const placement& p,
               std::vector<ecs::entity>& out, glm::dvec3 offset) {
    const ecs::entity e = world.create();
    world.emplace<world_transform>(
        e,
        {glm::dvec3(p.xz.x, terrain.height_at(p.xz.x, p.xz.y), p.xz.y) + offset, p.yaw, p.scale});
    world.emplace<bounds>(e, {k_radius * p.scale, k_center_height * p.scale});
    world.emplace<plant_instance>(e, {species_id(p.seed % 2), 0, p.seed});
    world.emplace<lod_state>(e);
    out.push_back(e);
}

// The spawner's steps (lod/eco_tiles.h): place, build tiles, create plants in order, align,
// create tile entities. `with_tiles` false: the same plants in the same order, no tiles.
void fill(test_scene& s, bool with_tiles, bool in_tile_order = true,
          std::size_t extra_plants = 10) {
    const glm::dvec3 offset{1e6, 5.0, -2e6};  // far from the origin, as world_offset does
    s.terrain = generate_terrain(1000.0, 129, 40.0f, 5, 0.005f, 3);
    const std::array<double, 4> area{-500.0, -500.0, 500.0, 500.0};
    s.plants = place_population(s.terrain, area, 20000, 2.0f, 0.7f, 1.3f, 90.0f, 8);
    std::vector<glm::dvec2> xz;
    for (const auto& p : s.plants) xz.push_back(p.xz);
    s.tree = build_eco_tiles(xz, area, 128);
    for (std::size_t i = 0; i < s.plants.size(); ++i)
        add_plant(s.world, s.terrain, s.plants[in_tile_order ? s.tree.order[i] : i],
                  s.plant_entities, offset);
    // Plants outside the tree (spawned later, say) are culled flat.
    const auto more =
        place_population(s.terrain, area, std::uint32_t(extra_plants), 2.0f, 0.7f, 1.3f, 90.0f, 99);
    for (const auto& p : more) add_plant(s.world, s.terrain, p, s.plant_entities, offset);
    s.world.align<world_transform, bounds, plant_instance, lod_state>();
    if (with_tiles)
        s.tiles = create_tile_entities(s.world, s.tree, s.terrain,
                                       {(k_center_height + k_radius) * 1.3f, 1.3f, offset});

    camera cam;
    cam.position = glm::dvec3(-100.0, s.terrain.height_at(-100.0, 50.0) + 20.0, 50.0) + offset;
    cam.forward = glm::normalize(glm::vec3(0.6f, -0.15f, -1.0f));
    cam.far_plane = 3000.0f;
    derive_camera_matrices(cam);
    s.world.emplace<camera>(s.world.create(), cam);
    species_library library;
    library.species.resize(2);
    library.species[0].max_distance_m = 300.0f;
    library.species[1].max_distance_m = 150.0f;
    s.world.set_resource(std::move(library));
    shadow_settings shadows;
    shadows.max_distance_m = 120.0f;
    s.world.set_resource(shadows);
    s.world.set_resource(lod_policy{});
}

void run_cull(ecs::world& world, int threads) {
    ecs::executor exec(threads);
    ecs::schedule schedule;
    schedule.add<cull_system>();
    schedule.run(world, exec);
}

std::vector<lod_state> lods(const ecs::world& world) {
    const auto& table = world.table<lod_state>();
    return {table.data(), table.data() + table.size()};
}

bool operator==(const lod_state& a, const lod_state& b) {
    return a.visible == b.visible && a.in_shadow_range == b.in_shadow_range;
}

TEST(eco_tile_entities, one_entity_per_node_with_handles_ranges_and_terrain_heights) {
    test_scene s;
    fill(s, true);
    ASSERT_EQ(s.tiles.size(), s.tree.nodes.size());
    for (std::size_t i = 0; i < s.tiles.size(); ++i) {
        const tile& t = s.world.get<tile>(s.tiles[i]);
        const eco_tile_node& n = s.tree.nodes[i];
        EXPECT_EQ(t.first_plant, n.first_plant);
        EXPECT_EQ(t.plant_count, n.plant_count);
        EXPECT_EQ(t.depth, n.depth);
        EXPECT_EQ(t.parent, n.parent == k_no_eco_tile ? ecs::entity{} : s.tiles[n.parent]);
        for (std::size_t q = 0; q < 4; ++q)
            EXPECT_EQ(t.children[q], n.is_leaf() ? ecs::entity{} : s.tiles[n.children[q]]);
        EXPECT_TRUE(s.world.has<tile_visibility>(s.tiles[i]));
        // Every plant's base is within the tile's terrain height range.
        for (std::uint32_t p = t.first_plant; p < t.first_plant + t.plant_count; ++p) {
            const double y = s.world.get<world_transform>(s.plant_entities[p]).position.y;
            ASSERT_GE(y, t.min_height - 1e-3);
            ASSERT_LE(y, t.max_height + 1e-3);
        }
    }
}

TEST(eco_tile_culling, equals_flat_culling_for_every_plant_and_culls_whole_tiles) {
    test_scene flat;
    fill(flat, false);
    run_cull(flat.world, 2);
    test_scene tiled;
    fill(tiled, true);
    run_cull(tiled.world, 2);
    const auto expected = lods(flat.world);
    const auto got = lods(tiled.world);
    ASSERT_EQ(expected.size(), got.size());
    std::size_t visible = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
        ASSERT_TRUE(got[i] == expected[i]) << "plant " << i;
        visible += got[i].visible;
    }
    EXPECT_GT(visible, 100u);
    EXPECT_LT(visible, got.size() / 2);
    // Some leaf tiles are culled, and every plant of a culled tile is culled.
    std::size_t culled_leaves = 0;
    std::size_t visible_leaves = 0;
    for (const ecs::entity e : tiled.tiles) {
        const tile& t = tiled.world.get<tile>(e);
        const tile_visibility& v = tiled.world.get<tile_visibility>(e);
        if (!t.parent.is_null() && tiled.world.get<tile_visibility>(t.parent).visible == 0 &&
            tiled.world.get<tile_visibility>(t.parent).in_shadow_range == 0) {
            EXPECT_EQ(v.visible + v.in_shadow_range, 0);  // culled parents cull their subtree
        }
        if (t.is_leaf()) visible_leaves += v.visible;
        if (!t.is_leaf() || v.visible || v.in_shadow_range) continue;
        ++culled_leaves;
        for (std::uint32_t p = t.first_plant; p < t.first_plant + t.plant_count; ++p)
            ASSERT_EQ(got[p].visible + got[p].in_shadow_range, 0);
    }
    EXPECT_GT(culled_leaves, 10u);
    EXPECT_GT(visible_leaves, 5u);
    std::printf("[          ] %zu of %zu plants visible; %zu leaf tiles visible, %zu culled\n",
                visible, got.size(), visible_leaves, culled_leaves);
}

TEST(eco_tile_culling, points_and_lines_draw_beyond_the_species_draw_distance) {
    // The same scene under the point/line policy: every plant the mesh levels drew is drawn,
    // plus the frustum's plants beyond 300 m / 150 m; still the same with and without tiles.
    test_scene meshes;
    fill(meshes, true);
    run_cull(meshes.world, 2);
    test_scene flat, tiled;
    fill(flat, false);
    fill(tiled, true);
    lod_policy points;
    points.mode = lod_policy::kind::points_lines;
    flat.world.set_resource(points);
    tiled.world.set_resource(points);
    run_cull(flat.world, 2);
    run_cull(tiled.world, 2);
    const auto by_distance = lods(meshes.world);
    const auto expected = lods(flat.world);
    const auto got = lods(tiled.world);
    std::size_t beyond = 0;
    const camera& cam = flat.world.table<camera>().data()[0];
    for (std::size_t i = 0; i < got.size(); ++i) {
        ASSERT_TRUE(got[i] == expected[i]) << "plant " << i;
        ASSERT_GE(got[i].visible, by_distance[i].visible) << "plant " << i;
        ASSERT_GE(got[i].in_shadow_range, by_distance[i].in_shadow_range) << "plant " << i;
        if (got[i].visible == by_distance[i].visible) continue;
        // Drawn now, culled before: only by distance, never outside the frustum.
        const auto& t = flat.world.get<world_transform>(flat.plant_entities[i]);
        const double r = glm::length(t.position - cam.position);
        EXPECT_GT(r, 150.0 * 0.7) << "plant " << i;
        ++beyond;
    }
    EXPECT_GT(beyond, 100u);
}

TEST(eco_tile_culling, tiles_outside_the_view_hide_their_plants) {
    test_scene s;
    fill(s, true, true, 0);
    // Mark every plant visible: culled tiles must reset their plants.
    auto& table = s.world.table<lod_state>();
    for (std::size_t i = 0; i < table.size(); ++i)
        table.data()[i] = {representation::none, representation::none, 1, 1};
    // Look straight up: no tile box is in the frustum; shadow range still keeps near tiles.
    camera& cam = s.world.single<camera>();
    cam.forward = {0.0f, 1.0f, 0.0f};
    cam.up = {0.0f, 0.0f, -1.0f};
    cam.position.y += 1000.0;  // and far above everything: nothing in shadow range either
    derive_camera_matrices(cam);
    run_cull(s.world, 2);
    for (const lod_state& lod : lods(s.world)) ASSERT_EQ(lod.visible + lod.in_shadow_range, 0);
    EXPECT_EQ(s.world.get<tile_visibility>(s.tiles[0]).visible, 0);
}

TEST(eco_tile_culling, same_result_on_1_2_and_4_threads) {
    std::vector<std::vector<lod_state>> results;
    std::vector<std::vector<std::uint8_t>> tile_results;
    for (const int threads : {1, 2, 4}) {
        test_scene s;
        fill(s, true);
        run_cull(s.world, threads);
        results.push_back(lods(s.world));
        std::vector<std::uint8_t> v;
        for (const ecs::entity e : s.tiles) {
            v.push_back(s.world.get<tile_visibility>(e).visible);
            v.push_back(s.world.get<tile_visibility>(e).in_shadow_range);
        }
        tile_results.push_back(v);
    }
    for (std::size_t r = 1; r < results.size(); ++r) {
        ASSERT_EQ(results[r].size(), results[0].size());
        for (std::size_t i = 0; i < results[0].size(); ++i)
            ASSERT_TRUE(results[r][i] == results[0][i]);
        EXPECT_EQ(tile_results[r], tile_results[0]);
    }
}

TEST(eco_tile_culling, plants_not_created_in_tile_order_are_detected) {
    test_scene s;
    fill(s, true, false);
    EXPECT_THROW(run_cull(s.world, 2), std::logic_error);
}

TEST(eco_tile_build, fifty_and_hundred_thousand_plants_place_and_tile_fast) {
    const heightfield terrain = generate_terrain(4000.0, 513, 60.0f, 5, 0.002f, 3);
    const std::array<double, 4> area{-2000.0, -2000.0, 2000.0, 2000.0};
    for (const std::uint32_t count : {50000u, 100000u}) {
        const auto t0 = std::chrono::steady_clock::now();
        const auto plants = place_population(terrain, area, count, 3.0f, 0.8f, 1.2f, 35.0f, 5);
        const auto t1 = std::chrono::steady_clock::now();
        std::vector<glm::dvec2> xz;
        xz.reserve(plants.size());
        for (const auto& p : plants) xz.push_back(p.xz);
        const eco_tile_tree tree = build_eco_tiles(xz, area, 256);
        ecs::world world;
        const auto tiles = create_tile_entities(world, tree, terrain, {20.0f, 1.2f, {}});
        const auto t2 = std::chrono::steady_clock::now();
        const double place_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
        const double tile_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
        std::printf("[          ] %zu plants: placement %.1f ms, eco tiles (%zu nodes) %.1f ms\n",
                    plants.size(), place_ms, tiles.size(), tile_ms);
        EXPECT_LT(place_ms + tile_ms, 1000.0);
    }
}

}  // namespace
}  // namespace sylva
