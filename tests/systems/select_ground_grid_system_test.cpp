// The ground tiles' grids (systems/select_ground_grid_system.h), by hand: each tile on the
// coarsest grid whose error shows under the tolerance from the camera, the tolerance from the
// ground_lod resource, every tile on its own samples for a full-geometry camera, the same for any
// thread count.
#include "systems/select_ground_grid_system.h"

#include <gtest/gtest.h>

#include "ecs/executor.h"
#include "ecs/schedule.h"
#include "systems/update_camera_system.h"

namespace sylva {
namespace {

// Camera at the origin (55°, 540 px: pixels_per_radian = 540 / 0.9599311 = 562.54). Tiles of
// radius 10 m at 100 m and 1000 m (nearest points 90 m and 990 m), behind and ahead alike, with
// grid errors 0, 0.05, 0.2 and 1 m.
struct ground_scene {
    ecs::world world;
    ecs::schedule schedule;

    explicit ground_scene(float tolerance_px, bool full_geometry = false) {
        for (const double z : {-100.0, 1000.0, 100.0}) {
            ground_tile tile;
            tile.centre = {0.0, 0.0, z};
            tile.radius = 10.0f;
            tile.grids = 4;
            tile.grid_error_m = {0.0f, 0.05f, 0.2f, 1.0f};
            world.emplace<ground_tile>(world.create(), tile);
        }
        camera cam;
        cam.full_geometry = full_geometry;
        derive_camera_matrices(cam);
        cam.pixels_per_radian = cam.viewport_height_px / cam.fov_y;
        world.emplace<camera>(world.create(), cam);
        world.set_resource(ground_lod{tolerance_px});
        schedule.add<select_ground_grid_system>();
        schedule.build();
    }
    std::array<int, 3> grids(int threads) {
        ecs::executor executor(threads);
        schedule.run(world, executor);
        const ground_tile* t = world.table<ground_tile>().data();
        return {t[0].grid, t[1].grid, t[2].grid};
    }
};

// Half a pixel from 90 m: errors up to 0.5 x 90 / 562.54 = 0.0800 m, grid 1 (0.05) not grid 2
// (0.2); from 990 m up to 0.880 m, grid 2 not grid 3 (1 m). Two pixels: 0.320 m, grid 2, and
// 3.52 m, grid 3.
TEST(select_ground_grid, each_tile_takes_the_coarsest_grid_under_the_tolerance) {
    EXPECT_EQ(ground_scene(0.5f).grids(1), (std::array<int, 3>{1, 2, 1}));
    EXPECT_EQ(ground_scene(0.5f).grids(4), (std::array<int, 3>{1, 2, 1}));
    EXPECT_EQ(ground_scene(2.0f).grids(2), (std::array<int, 3>{2, 3, 2}));
    EXPECT_EQ(ground_scene(0.0f).grids(2), (std::array<int, 3>{0, 0, 0}));
    EXPECT_EQ(ground_scene(64.0f, true).grids(2), (std::array<int, 3>{0, 0, 0}))
        << "the reference's camera";
}

}  // namespace
}  // namespace sylva
