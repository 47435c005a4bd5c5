// Skipping shadow cascades that shade only air (resources/shadow_receivers.h): the receivers'
// height grid and the slice test, against hand-computed corners.
#include "resources/shadow_receivers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "systems/update_camera_system.h"

namespace sylva {
namespace {

// 100 m of flat ground at height 0, centred on the origin, on 10 cells of 10 m.
heightfield flat_ground() {
    heightfield f;
    f.resolution = 11;
    f.size_m = 100.0;
    f.heights.assign(11 * 11, 0.0f);
    return f;
}

// A level camera `height` m up at the origin looking down -z, 90° wide each way: at view depth d
// the frustum spans x and y ±d, so a slice's lowest corner is `height` − far.
camera level_camera(double height) {
    camera cam;
    cam.position = {0.0, height, 0.0};
    cam.forward = {0.0f, 0.0f, -1.0f};
    cam.fov_y = float(std::numbers::pi / 2.0);
    cam.aspect = 1.0f;
    cam.viewport_height_px = 100.0f;
    derive_camera_matrices(cam);
    return cam;
}

TEST(shadow_receivers, the_grid_keeps_the_highest_ground_and_plant_per_cell) {
    receiver_heights r = make_receiver_heights(flat_ground(), glm::dvec3(0.0), 10);
    EXPECT_EQ(r.cells, 10u);
    EXPECT_DOUBLE_EQ(r.cell_m, 10.0);
    EXPECT_FLOAT_EQ(r.highest({-50.0, -50.0}, {50.0, 50.0}), 0.0f);
    // A plant at (15, -15), 2 m wide, its top at 12 m: the cell [10, 20] x [-20, -10] only.
    r.raise(15.0, -15.0, 2.0, 12.0f);
    EXPECT_FLOAT_EQ(r.highest({11.0, -19.0}, {19.0, -11.0}), 12.0f);
    EXPECT_FLOAT_EQ(r.highest({-50.0, -50.0}, {9.0, 50.0}), 0.0f);
    EXPECT_FLOAT_EQ(r.highest({-50.0, -50.0}, {50.0, 50.0}), 12.0f);
    // Beyond the grid nothing is known.
    EXPECT_EQ(r.highest({40.0, 40.0}, {60.0, 45.0}), std::numeric_limits<float>::infinity());
    // The world offset moves the grid.
    const receiver_heights moved =
        make_receiver_heights(flat_ground(), glm::dvec3(1000.0, 5.0, 0.0), 10);
    EXPECT_FLOAT_EQ(moved.highest({960.0, -10.0}, {1040.0, 10.0}), 5.0f);
    EXPECT_EQ(moved.highest({-10.0, -10.0}, {10.0, 10.0}), std::numeric_limits<float>::infinity());
}

TEST(shadow_receivers, a_slice_wholly_above_every_receiver_holds_none) {
    receiver_heights r = make_receiver_heights(flat_ground(), glm::dvec3(0.0), 10);
    // The slice between view depths 10 and 20 of a camera 30 m up: its lowest corners are at
    // 30 − 20 = 10 m, over x in [-20, 20] and z in [-20, -10].
    const camera cam = level_camera(30.0);
    EXPECT_FALSE(slice_may_hold_receivers(r, cam, 10.0f, 20.0f));
    // A plant under that footprint whose top reaches 12 m is a receiver in it ...
    r.raise(5.0, -15.0, 1.0, 12.0f);
    EXPECT_TRUE(slice_may_hold_receivers(r, cam, 10.0f, 20.0f));
    // ... and the deeper slice from 20 to 40 reaches down to the ground (30 − 40 < 0).
    receiver_heights ground = make_receiver_heights(flat_ground(), glm::dvec3(0.0), 10);
    EXPECT_TRUE(slice_may_hold_receivers(ground, cam, 20.0f, 40.0f));
    // A camera 29 m up: the slice's lowest corners at 9 m are still above the bare ground.
    EXPECT_FALSE(slice_may_hold_receivers(ground, level_camera(29.0), 10.0f, 20.0f));
    // No grid: every slice may hold receivers.
    EXPECT_TRUE(slice_may_hold_receivers(receiver_heights{}, cam, 10.0f, 20.0f));
}

}  // namespace
}  // namespace sylva
