// A scenario's Wang-tiled populations (setup/wang_populations.h): their plants are the tiling's,
// keep their spacing, follow the density their count asks, and are the same plants as the
// spawned world holds.
#include "setup/wang_populations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>

#include "components/transform.h"
#include "scenarios/scenario_loader.h"
#include "setup/spawn_scenario.h"

namespace sylva {
namespace {

scenario wang_meadow() {
    return load_scenario_text(R"({
        "seed": 4,
        "terrain": {"size_m": 200},
        "wang_tiles": {"tile_size_m": 25, "colours": 2},
        "species": [{"name": "oak"}, {"name": "bush", "generator": "shrub"}],
        "populations": [
            {"species": "oak", "count": 150, "min_spacing_m": 4, "placement": "wang_tiles",
             "area": [-60, -40, 70, 55]},
            {"species": "bush", "count": 900, "min_spacing_m": 2, "placement": "wang_tiles",
             "area": [-60, -40, 70, 55]}]})",
                              "wang_meadow.json");
}

TEST(wang_populations, plants_follow_the_count_keep_the_spacing_and_stay_in_the_area) {
    const scenario s = wang_meadow();
    for (std::size_t p = 0; p < 2; ++p) {
        SCOPED_TRACE(p);
        const population_settings& pop = s.populations[p];
        const std::vector<placement> plants = place_wang_population(s, p, 0.0f);
        // Darts are thrown for count over the area: within 10 % when the spacing leaves room.
        EXPECT_NEAR(double(plants.size()), double(pop.count), 0.1 * double(pop.count));
        double nearest = 1e9;
        for (std::size_t a = 0; a < plants.size(); ++a) {
            EXPECT_GE(plants[a].xz.x, pop.area[0]);
            EXPECT_LT(plants[a].xz.y, pop.area[3]);
            for (std::size_t b = a + 1; b < plants.size(); ++b)
                nearest = std::min(nearest, glm::length(plants[a].xz - plants[b].xz));
        }
        EXPECT_GE(nearest, double(pop.min_spacing_m));
    }
}

// Both populations lie on one lattice with one tiling: the same tile types in the same places.
// Plants that reach farther than the tiles allow are refused with the population named.
TEST(wang_populations, a_reach_too_wide_for_the_tiles_names_the_population) {
    const scenario s = wang_meadow();
    try {
        wang_tile_set_of(s, 0, 9.0f);  // w = 9, m = 9 + 4/√2: 2 (m + w) = 41.7 m > 25 m
        ADD_FAILURE() << "built";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/populations/0 (oak): a tile of 25 m is too small for plants that reach 9 m"),
                  std::string::npos)
            << e.what();
    }
}

TEST(wang_populations, populations_share_the_tiling_and_differ_in_their_sets) {
    const scenario s = wang_meadow();
    EXPECT_EQ(wang_lattice_origin(s), glm::dvec2(-100.0, -100.0));
    const wang_tile_set oaks = wang_tile_set_of(s, 0, 0.0f);
    const wang_tile_set bushes = wang_tile_set_of(s, 1, 0.0f);
    EXPECT_EQ(oaks.rules.tile_size_m, bushes.rules.tile_size_m);
    EXPECT_NE(oaks.tiles[0].size(), bushes.tiles[0].size());
    EXPECT_NEAR(oaks.rules.plants_per_m2, 150.0 / (130.0 * 95.0), 1e-12);
    // The oaks of lattice tile (2, 3), inside the area, are tile type wang_tile_at(seed, 2, 3)
    // moved there.
    const std::uint32_t type = wang_tile_at(wang_tiling_seed(s), 2, 3, 2);
    const std::vector<placement> all = place_wang_population(s, 0, 0.0f);
    std::size_t in_tile = 0;
    for (const placement& p : all) {
        const glm::dvec2 local = p.xz - glm::dvec2(-100.0 + 50.0, -100.0 + 75.0);
        if (local.x >= 0.0 && local.x < 25.0 && local.y >= 0.0 && local.y < 25.0) {
            ASSERT_LT(in_tile, oaks.tiles[type].size());
            EXPECT_NEAR(glm::length(local - oaks.tiles[type][in_tile].xz), 0.0, 1e-9);
            ++in_tile;
        }
    }
    EXPECT_EQ(in_tile, oaks.tiles[type].size());
}

// The spawned world's plants are the tiling's, position for position.
TEST(wang_populations, the_spawned_world_holds_the_tilings_plants) {
    scenario s = load_scenario_text(R"({
        "seed": 5, "terrain": {"size_m": 120, "resolution": 17, "height_m": 1},
        "wang_tiles": {"tile_size_m": 60},
        "species": [{"name": "bush", "generator": "shrub", "height_m": 1.5}],
        "populations": [{"species": "bush", "count": 40, "min_spacing_m": 6, "placement": "wang_tiles",
                         "area": [-30, -30, 30, 30]}]})",
                                    "spawned.json");
    const scene_assets assets = build_scene_assets(s, nullptr);
    ecs::world world;
    spawn_scenario(world, s, assets);
    std::vector<glm::dvec2> spawned;
    const auto& transforms = world.table<world_transform>();
    for (std::size_t i = 0; i < transforms.size(); ++i)
        spawned.emplace_back(transforms.data()[i].position.x, transforms.data()[i].position.z);
    const std::vector<placement> tiled = place_wang_population(s, 0, wang_reach_m(s, 0, assets));
    ASSERT_EQ(spawned.size(), tiled.size());
    for (const placement& p : tiled)
        EXPECT_TRUE(std::any_of(spawned.begin(), spawned.end(), [&](glm::dvec2 q) { return glm::length(q - p.xz) < 1e-6; }))
            << p.xz.x << ", " << p.xz.y;
}

}  // namespace
}  // namespace sylva
