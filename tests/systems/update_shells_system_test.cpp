// The shells' per-frame state (systems/update_shells_system.h), by hand: the handover band is the
// farthest any species' ladder asks, a tile behind the camera is not drawn, and a tile's slices
// follow the coarsest ground grid whose error stays under a pixel.
#include "systems/update_shells_system.h"

#include <gtest/gtest.h>

#include "ecs/executor.h"
#include "ecs/schedule.h"
#include "lod/point_line_lod.h"
#include "systems/update_camera_system.h"

namespace sylva {
namespace {

ladder to_shell_below(float px) {
    ladder l;
    l.count = 2;
    l.rungs = {representation::mesh_full, representation::shell};
    l.below_px = {0.0f, px};
    l.band = {0.0f, 0.5f};
    return l;
}

// Camera at the origin looking down -z (55°, 540 px). Two species of bounding radius 5 m and
// 1 m, both ending in a shell below 20 px (band 0.5). Tile A 100 m ahead, tile B 100 m behind,
// both of radius 10 m, with ground grid errors 0, 0.05, 0.2 and 1 m.
struct shell_scene {
    ecs::world world;
    ecs::schedule schedule;

    shell_scene() {
        species_library library;
        species_entry big, small;
        big.bounding_radius = 5.0f;
        small.bounding_radius = 1.0f;
        library.species = {small, big};
        lod_policy policy;
        policy.mode = lod_policy::kind::ladder;
        policy.ladders = {to_shell_below(20.0f), to_shell_below(20.0f)};
        shell_view view;
        view.active = true;
        view.slice_height_m = 1.0f;
        view.max_level = 4;
        view.mean_scale = {1.0f, 1.0f};
        for (const double z : {-100.0, 100.0}) {
            shell_tile tile;
            tile.centre = {0.0f, 0.0f, float(z)};
            tile.radius = 10.0f;
            tile.grids = 4;
            tile.grid_error_m = {0.0f, 0.05f, 0.2f, 1.0f};
            world.emplace<shell_tile>(world.create(), tile);
        }
        camera cam;
        derive_camera_matrices(cam);
        world.emplace<camera>(world.create(), cam);
        world.set_resource(std::move(library));
        world.set_resource(std::move(policy));
        world.set_resource(std::move(view));
        schedule.add<update_shells_system>();
        schedule.build();
    }
};

TEST(update_shells, the_band_is_the_farthest_asked_and_a_tile_follows_the_coarsest_grid_under_a_pixel) {
    shell_scene scene;
    ecs::executor executor(2);
    scene.schedule.run(scene.world, executor);
    const shell_view& view = scene.world.resource<shell_view>();
    // One pixel is 2 tan(27.5°) / 540 = 0.0019281 on the image plane at 1 m. The big species'
    // 10 m diameter is 20 px at 10 / (20 x 0.0019281) = 259.3 m and 30 px at 172.9 m.
    const double pixel = image_plane_units(1.0, 0.9599311, 540.0);
    EXPECT_NEAR(pixel, 0.0019281, 1e-6);
    EXPECT_NEAR(view.fade_end_m, 10.0 / (20.0 * pixel), 1e-2);
    EXPECT_NEAR(view.fade_start_m, 10.0 / (30.0 * pixel), 1e-2);
    EXPECT_NEAR(view.fade_end_m, 259.3, 0.1);
    EXPECT_FLOAT_EQ(view.plant_diameter_m, 10.0f);
    const shell_tile* tiles = scene.world.table<shell_tile>().data();
    EXPECT_TRUE(tiles[0].visible);
    EXPECT_FALSE(tiles[1].visible) << "behind the camera";
    // Nearest point 90 m away: an error shows under a pixel up to 90 x 0.0019281 = 0.174 m, so
    // grid 1 (0.05 m) and not grid 2 (0.2 m).
    EXPECT_EQ(tiles[0].grid, 1u);
    // λ = log2(90 x 2 / (1 x 1 / 0.0019281)) = log2(0.347) < 0: level 0.
    EXPECT_EQ(tiles[0].level.level, 0u);
}

}  // namespace
}  // namespace sylva
