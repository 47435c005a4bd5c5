// Numerical stress: the same scene placed 1e4, 1e5 and 1e6 m from the origin renders like the
// scene at the origin. Positions are double precision and rendering is camera-relative, so
// only the shadow texel grid (pinned to the world, so its phase moves with the offset) may
// differ a little. Tolerance: PSNR above 45 dB and under 1 % of pixels off by more than 16.
// A camera path moved by the offset is the origin's path moved by the offset (no jitter).
#include <gtest/gtest.h>

#include <cmath>

#include "../gl/gl_test_support.h"
#include "app/stress/stress_checks.h"
#include "components/camera.h"
#include "scenarios/camera_path.h"
#include "stress_support.h"

namespace sylva {
namespace {

TEST(world_offset, scenes_far_from_the_origin_render_like_the_origin) {
    SYLVA_REQUIRE_GL();
    const auto rows = check_world_offset_renders(*testing::shared_gl_context(), 2);
    ASSERT_EQ(rows.size(), 3u);  // 1e4, 1e5, 1e6 m
    testing::expect_all_pass(rows);
    for (const stress_row& r : rows) EXPECT_GT(r.value, 45.0) << r.check;
}

TEST(world_offset, camera_paths_far_from_the_origin_do_not_jitter) {
    const auto rows = check_camera_path_offsets();
    ASSERT_EQ(rows.size(), 3u);
    testing::expect_all_pass(rows);
    // Double precision: 1e6 m has a spacing of 1.2e-10 m, so the path is exact to a few ulps
    // there; a float path would be off by up to 0.03 m (its spacing at 1e6 is 0.0625 m).
    EXPECT_LT(testing::row_named(rows, "camera path at 1e+06").value, 1e-8);
}

TEST(world_offset, a_hand_built_two_key_path_is_shifted_exactly) {
    const glm::dvec3 offset{1e6, 0.0, -1e6};
    std::vector<camera_keyframe> near_keys = {{0.0, {0.0, 2.0, 0.0}, {0.0, 2.0, -10.0}, 55.0f},
                                              {4.0, {8.0, 2.0, 0.0}, {8.0, 2.0, -10.0}, 55.0f}};
    std::vector<camera_keyframe> far_keys = near_keys;
    for (auto& k : far_keys) k.position += offset, k.target += offset;
    // Two keys: the reflected end neighbours make the spline a straight line at 2 m/s.
    const camera_pose half = sample_camera_path(far_keys, 2.0);
    EXPECT_NEAR(half.position.x - offset.x, 4.0, 1e-9);
    EXPECT_NEAR(half.position.z - offset.z, 0.0, 1e-9);
    EXPECT_NEAR(sample_camera_path(near_keys, 2.0).position.x, 4.0, 1e-12);
}

}  // namespace
}  // namespace sylva
