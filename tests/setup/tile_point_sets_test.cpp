// Deussen 2002 §6.2: each eco tile's aggregated point set is built from its plants' point
// lists in proportion to their area, merged up the tile hierarchy, in world space relative to
// the tile; a tile is drawn as its set only where Eq. 1 asks for no more samples than it has.
#include "setup/tile_point_sets.h"

#include <gtest/gtest.h>

#include "components/plant_instance.h"
#include "components/tile.h"
#include "components/transform.h"
#include "systems/aggregate_eco_tiles_system.h"
#include "lod/eco_tiles.h"

namespace sylva {
namespace {

// Two species of one point part each (600 points at the model origin, area 4 m² and 12 m²),
// four plants in four quadrants of a 100 m square: a root tile and four leaves of one plant.
struct tiled_scene {
    ecs::world world;
    scene_assets assets;

    tiled_scene() {
        for (int s = 0; s < 2; ++s) {
            species_entry sp;
            sp.texture_layer = float(s);
            sp.first_lod_part = std::uint32_t(s);
            sp.lod_part_count = 1;
            sp.cell_count = 1;
            assets.library.species.push_back(sp);
            lod_part_entry part;
            part.area_m2 = s == 0 ? 4.0f : 12.0f;
            part.primitive_count = 600;
            part.mesh_primitives = std::uint16_t(assets.meshes.size());
            assets.library.lod_parts.push_back(part);
            mesh_data points;
            points.primitive = primitive_kind::points;
            points.vertices.assign(600, vertex{});
            points.submeshes.push_back({0, 600, material_kind::leaf});
            assets.meshes.push_back(points);
            assets.library.meshes.push_back({600, representation::points, primitive_kind::points});
        }
        const std::vector<glm::dvec2> xz{{-25.0, -25.0}, {25.0, -25.0}, {-25.0, 25.0}, {25.0, 25.0}};
        const eco_tile_tree tree = build_eco_tiles(xz, {-50.0, -50.0, 50.0, 50.0}, 1);
        for (const std::uint32_t i : tree.order) {
            const ecs::entity e = world.create();
            world.emplace<world_transform>(e, {{xz[i].x, 0.0, xz[i].y}, 0.0f, i == 3 ? 2.0f : 1.0f});
            world.emplace<plant_instance>(e, {species_id{std::uint16_t(i % 2)}, 0, 0});
        }
        world.align<world_transform, plant_instance>();
        heightfield flat;
        flat.resolution = 2;
        flat.size_m = 100.0;
        flat.heights.assign(4, 0.0f);
        create_tile_entities(world, tree, flat, {0.0f, 1.0f, {}});
    }
};

TEST(tile_point_sets, leaves_take_their_plants_points_and_the_root_merges_its_children) {
    tiled_scene scene;
    const std::size_t meshes_before = scene.assets.meshes.size();
    const tile_point_sets sets = build_tile_point_sets(scene.world, scene.assets, 7);
    ASSERT_EQ(sets.first_part.size(), 6u);  // root + 4 leaves, + end
    // Root: one set per species; each leaf: its plant's species only.
    EXPECT_EQ(sets.first_part[1] - sets.first_part[0], 2u);
    for (std::size_t t = 1; t < 5; ++t) EXPECT_EQ(sets.first_part[t + 1] - sets.first_part[t], 1u) << t;
    EXPECT_EQ(scene.assets.meshes.size(), meshes_before + 6);
    for (std::size_t t = 1; t < 5; ++t) {
        const tile_point_part& leaf = sets.parts[sets.first_part[t]];
        // One plant: all its 600 points (under k_tile_samples), its area scaled by scale².
        EXPECT_EQ(leaf.count, 600u);
        const tile& tl = scene.world.table<tile>().data()[t];
        const auto& plant = scene.world.table<world_transform>().data()[tl.first_plant];
        const float scale2 = plant.scale * plant.scale;
        const float species_area = scene.world.table<plant_instance>().data()[tl.first_plant].species == species_id{0}
                                       ? 4.0f
                                       : 12.0f;
        EXPECT_FLOAT_EQ(leaf.area_m2, species_area * scale2);
        // Every point sits at its plant, relative to the tile's origin.
        const glm::vec3 expected(plant.position - sets.origin[t]);
        for (const vertex& v : scene.assets.meshes[leaf.mesh].vertices) EXPECT_EQ(v.position, expected);
    }
    // The root's species-1 set merges plants 1 and 3 (areas 12 and 48 m², 600 points each): one
    // density for both, capped by plant 3's 600 / 48 = 12.5 per m² (below 1024 / 60), so
    // 150 + 600 = 750 points, shared 1 : 4 like the areas.
    const tile_point_part& root1 = sets.parts[sets.first_part[0] + 1];
    EXPECT_FLOAT_EQ(root1.area_m2, 12.0f + 48.0f);
    EXPECT_EQ(root1.count, 750u);
    std::size_t at_plant_3 = 0;
    const glm::vec3 plant3(glm::dvec3(25.0, 0.0, 25.0) - sets.origin[0]);
    for (const vertex& v : scene.assets.meshes[root1.mesh].vertices) at_plant_3 += v.position == plant3;
    EXPECT_EQ(at_plant_3, 600u);
}

TEST(tile_point_sets, a_tile_draws_the_share_of_eq1_its_set_holds_samples_for) {
    tile_point_sets sets;
    sets.first_part = {0, 1};
    tile_point_part part;
    part.area_m2 = 100.0f;
    part.count = 1000;
    sets.parts = {part};
    std::vector<std::uint32_t> counts(1, 0);
    std::vector<std::uint8_t> splats(1, 0);
    // p = ½·100 / r² / d'², d' = 0.004: r = 1000 → 3.125 points; r = 50 → 1250 > 1000, so the
    // set can draw 1000 / 1250 = 0.8 of the tile (its plants' own points the rest).
    EXPECT_EQ(tile_prefixes(sets, 0, 1000.0, 0.004, 1.0, counts, splats), 1.0);
    EXPECT_EQ(counts[0], 3u);
    EXPECT_DOUBLE_EQ(tile_prefixes(sets, 0, 50.0, 0.004, 1.0, counts, splats), 0.8);
    EXPECT_EQ(counts[0], 1000u);
}

TEST(tile_point_sets, a_line_set_draws_q_times_the_lines_its_tile_stands_for) {
    tile_point_sets sets;
    sets.first_part = {0, 1};
    tile_point_part part;
    part.primitive = lod_primitive::lines;
    part.area_m2 = 18.0f;        // 1000 blades of 0.018 m²
    part.line_length_m = 500.0f;  // 1000 blades of 0.5 m
    part.line_error_m = 0.01f;
    part.count = 200;  // the set holds 200 of them
    part.stands_for = 1000;
    sets.parts = {part};
    std::vector<std::uint32_t> counts(1, 0);
    std::vector<std::uint8_t> splats(1, 0);
    // q = A / (r·l·d') = 18 / (r · 500 · 0.004): r = 60 → 0.15 → 150 of the 1000 lines (the set
    // has them); r = 30 → 0.3 → 300 lines, more than the set holds: it draws 200 / 300 of the tile.
    EXPECT_EQ(tile_prefixes(sets, 0, 60.0, 0.004, 1.0, counts, splats), 1.0);
    EXPECT_EQ(counts[0], 150u);
    EXPECT_EQ(splats[0], 0);
    EXPECT_DOUBLE_EQ(tile_prefixes(sets, 0, 30.0, 0.004, 1.0, counts, splats), 2.0 / 3.0);
    // r = 90: a line's image is l / (2r·n_l) = 500 / 180,000 = 0.0028 < d', so the set draws
    // splats at its lines' ends, Eq. 1's p = c_p·½·18 / 90² / 0.004² = 69.4 → 69 (nearest).
    EXPECT_EQ(tile_prefixes(sets, 0, 90.0, 0.004, 1.0, counts, splats), 1.0);
    EXPECT_EQ(counts[0], 69u);
    EXPECT_EQ(splats[0], 1);
}

TEST(tile_point_sets, a_tile_hands_over_over_a_ramp_beyond_three_radii_and_the_shadows) {
    // Radius 10 m: nothing nearer than 30 m, all from 30 · 1.25 = 37.5 m, linear between.
    EXPECT_EQ(tile_distance_share(29.0, 10.0, 0.0), 0.0);
    EXPECT_EQ(tile_distance_share(30.0, 10.0, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(tile_distance_share(33.75, 10.0, 0.0), 0.5);
    EXPECT_EQ(tile_distance_share(37.5, 10.0, 0.0), 1.0);
    EXPECT_EQ(tile_distance_share(500.0, 10.0, 0.0), 1.0);
    // A tile reaching into the shadow distance (120 m) casts: its plants draw it.
    EXPECT_EQ(tile_distance_share(125.0, 10.0, 120.0), 0.0);
    EXPECT_EQ(tile_distance_share(131.0, 10.0, 120.0), 1.0);
}

}  // namespace
}  // namespace sylva
