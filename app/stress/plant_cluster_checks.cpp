// Point clusters (app/stress/stress_checks.h): eco tiles (lod/eco_tiles.h) over plants that all
// stand at one point or on a line stay bounded, hold every plant once, and cull like no tiles.
#include <algorithm>
#include <array>
#include <functional>
#include <glm/geometric.hpp>
#include <span>

#include "app/stress/check_support.h"
#include "app/stress/stress_checks.h"
#include "components/camera.h"
#include "components/bounds.h"
#include "components/lod_state.h"
#include "components/plant_instance.h"
#include "components/transform.h"
#include "ecs/executor.h"
#include "ecs/schedule.h"
#include "lod/eco_tiles.h"
#include "models/terrain/terrain.h"
#include "systems/cull_system.h"
#include "systems/update_camera_system.h"

namespace sylva {
namespace {

using stress::row;
using stress::rows;
using stress::text;
struct cluster_case {
    const char* name;
    std::function<glm::dvec2(std::size_t, std::size_t)> at;  // plant i of n
};

struct tree_stats {
    std::uint16_t depth = 0;
    std::size_t nodes = 0;
    bool one_leaf_each = false;  // every plant in exactly one leaf, inside it
};

tree_stats inspect_tree(const eco_tile_tree& tree, std::span<const glm::dvec2> xz) {
    tree_stats s;
    s.nodes = tree.nodes.size();
    std::vector<int> seen(xz.size(), 0);
    bool inside = tree.order.size() == xz.size();
    for (const eco_tile_node& n : tree.nodes) {
        s.depth = std::max(s.depth, n.depth);
        if (!n.is_leaf()) continue;
        for (std::uint32_t slot = n.first_plant; slot < n.first_plant + n.plant_count; ++slot) {
            const std::uint32_t plant = tree.order[slot];
            ++seen[plant];
            const glm::dvec2 p = xz[plant];
            inside = inside && p.x >= n.min.x && p.x <= n.min.x + n.size && p.y >= n.min.y &&
                     p.y <= n.min.y + n.size;
        }
    }
    s.one_leaf_each = inside && std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; });
    return s;
}

// The spawner's steps (lod/eco_tiles.h) for plants at `xz`, 1e6 m from the origin, with or
// without tile entities; then one cull. Returns each plant's (visible, in_shadow_range).
std::vector<lod_state> cull_plants(std::span<const glm::dvec2> xz, const eco_tile_tree* tree,
                                   const heightfield& terrain, int threads) {
    const glm::dvec3 offset{1e6, 0.0, 1e6};
    ecs::world world;
    for (std::size_t slot = 0; slot < xz.size(); ++slot) {
        const glm::dvec2 p = xz[tree ? tree->order[slot] : slot];
        const ecs::entity e = world.create();
        world.emplace<world_transform>(
            e, {glm::dvec3(p.x, terrain.height_at(p.x, p.y), p.y) + offset, 0.0f, 1.0f});
        world.emplace<bounds>(e, {3.0f, 4.0f});
        world.emplace<plant_instance>(e, {species_id(slot % 2), 0, std::uint32_t(slot)});
        world.emplace<lod_state>(e);
    }
    world.align<world_transform, bounds, plant_instance, lod_state>();
    if (tree) create_tile_entities(world, *tree, terrain, {7.0f, 1.0f, offset});
    camera cam;
    cam.position = glm::dvec3(-45.0, terrain.height_at(-45.0, 45.0) + 12.0, 45.0) + offset;
    cam.forward = glm::normalize(glm::vec3(1.0f, -0.2f, -1.0f));
    derive_camera_matrices(cam);
    world.emplace<camera>(world.create(), cam);
    species_library library;
    library.species.resize(2);
    library.species[0].max_distance_m = 80.0f;
    library.species[1].max_distance_m = 40.0f;
    world.set_resource(std::move(library));
    shadow_settings shadows;
    shadows.max_distance_m = 30.0f;
    world.set_resource(shadows);
    world.set_resource(lod_policy{});
    ecs::executor executor(threads);
    ecs::schedule schedule;
    schedule.add<cull_system>();
    schedule.run(world, executor);
    const auto& table = world.table<lod_state>();
    std::vector<lod_state> by_plant(xz.size());
    for (std::size_t slot = 0; slot < xz.size(); ++slot)
        by_plant[tree ? tree->order[slot] : slot] = table.data()[slot];
    return by_plant;
}

}  // namespace

rows check_plant_clusters(int threads) {
    constexpr std::size_t k_plants = 2000;
    constexpr std::uint32_t k_per_tile = 16;
    const std::array<double, 4> area{-50.0, -50.0, 50.0, 50.0};
    const heightfield terrain = generate_terrain(120.0, 33, 8.0f, 3, 0.015f, 11);
    const auto along = [](std::size_t i, std::size_t n) {
        return -40.0 + 80.0 * double(i) / double(n - 1);
    };
    const cluster_case cases[] = {
        {"one point", [](std::size_t, std::size_t) { return glm::dvec2(3.7, -12.1); }},
        {"two points", [](std::size_t i,
                          std::size_t) { return i % 2 ? glm::dvec2(0.0) : glm::dvec2(1e-9, 0.0); }},
        {"x-parallel line",
         [&](std::size_t i, std::size_t n) { return glm::dvec2(along(i, n), 7.3); }},
        {"diagonal line",
         [&](std::size_t i, std::size_t n) { return glm::dvec2(along(i, n), along(i, n)); }},
        {"line on the split x = 0",
         [&](std::size_t i, std::size_t n) { return glm::dvec2(0.0, along(i, n)); }},
    };
    rows out;
    for (const cluster_case& c : cases) {
        std::vector<glm::dvec2> xz(k_plants);
        for (std::size_t i = 0; i < k_plants; ++i) xz[i] = c.at(i, k_plants);
        const eco_tile_tree tree = build_eco_tiles(xz, area, k_per_tile);
        const tree_stats s = inspect_tree(tree, xz);
        const std::vector<lod_state> flat = cull_plants(xz, nullptr, terrain, threads);
        const std::vector<lod_state> tiled = cull_plants(xz, &tree, terrain, threads);
        std::size_t mismatches = 0, visible = 0;
        for (std::size_t i = 0; i < k_plants; ++i) {
            mismatches += flat[i].visible != tiled[i].visible ||
                          flat[i].in_shadow_range != tiled[i].in_shadow_range;
            visible += flat[i].visible;
        }
        // Each subdivision that makes no progress adds 4 nodes per level: 4 x depth cap + 1
        // per group of k_per_tile + 1 plants bounds a tree of coincident plants.
        const std::size_t node_limit =
            (4 * k_max_eco_tile_depth + 1) * (k_plants / (k_per_tile + 1) + 1);
        out.push_back(
            row(text("eco tiles, %zu plants: %s", k_plants, c.name),
                text("depth %u, %zu nodes, %zu cull diffs", unsigned(s.depth), s.nodes, mismatches),
                double(mismatches),
                text("depth <= %u, 1 leaf/plant, 0 diffs", unsigned(k_max_eco_tile_depth)),
                s.depth <= k_max_eco_tile_depth && s.nodes <= node_limit && s.one_leaf_each &&
                    mismatches == 0 && visible > 0,
                text("%zu plants visible%s", visible,
                     s.one_leaf_each ? "" : "; a plant is not in exactly one leaf")));
    }
    return out;
}

}  // namespace sylva
