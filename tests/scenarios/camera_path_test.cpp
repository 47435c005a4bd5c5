#include "scenarios/camera_path.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <vector>

namespace sylva {
namespace {

// Uneven in time and in space on purpose: the spline must cope with both.
std::vector<camera_keyframe> winding_path() {
    return {{0.0, {0.0, 2.0, 0.0}, {0.0, 1.0, -10.0}, 50.0f},
            {2.0, {10.0, 3.0, -5.0}, {12.0, 1.0, -20.0}, 55.0f},
            {3.0, {12.0, 2.5, -20.0}, {0.0, 0.0, -30.0}, 40.0f},
            {7.0, {-8.0, 6.0, -40.0}, {-20.0, 2.0, -45.0}, 70.0f},
            {8.5, {-9.0, 6.0, -41.0}, {-25.0, 2.0, -45.0}, 70.0f}};
}

TEST(sample_camera_path, passes_exactly_through_every_key) {
    const auto keys = winding_path();
    for (const camera_keyframe& k : keys) {
        const camera_pose p = sample_camera_path(keys, k.time_s);
        EXPECT_EQ(p.position, k.position) << k.time_s;
        EXPECT_EQ(p.target, k.target) << k.time_s;
        EXPECT_EQ(p.fov_deg, k.fov_deg) << k.time_s;
    }
}

TEST(sample_camera_path, holds_the_end_poses_outside_the_key_range) {
    const auto keys = winding_path();
    EXPECT_EQ(sample_camera_path(keys, -5.0).position, keys.front().position);
    EXPECT_EQ(sample_camera_path(keys, 100.0).target, keys.back().target);
}

TEST(sample_camera_path, one_key_is_a_constant_pose_and_none_is_the_default) {
    const std::vector<camera_keyframe> one = {{4.0, {1.0, 2.0, 3.0}, {4.0, 5.0, 6.0}, 33.0f}};
    for (double t : {-1.0, 4.0, 10.0}) {
        const camera_pose p = sample_camera_path(one, t);
        EXPECT_EQ(p.position, one[0].position);
        EXPECT_EQ(p.target, one[0].target);
        EXPECT_EQ(p.fov_deg, 33.0f);
    }
    const camera_pose none = sample_camera_path({}, 1.0);
    EXPECT_EQ(none.position, camera_pose{}.position);
}

TEST(sample_camera_path, field_of_view_is_linear_in_time) {
    const auto keys = winding_path();
    EXPECT_FLOAT_EQ(sample_camera_path(keys, 1.0).fov_deg, 52.5f);
    EXPECT_FLOAT_EQ(sample_camera_path(keys, 5.0).fov_deg, 55.0f);
}

TEST(sample_camera_path, velocity_is_continuous_across_keys) {
    // One-sided finite differences at each interior key agree to O(h * acceleration).
    const auto keys = winding_path();
    constexpr double h = 1e-5;
    for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
        const double t = keys[i].time_s;
        for (auto field : {&camera_pose::position, &camera_pose::target}) {
            const glm::dvec3 before = sample_camera_path(keys, t - h).*field;
            const glm::dvec3 at = sample_camera_path(keys, t).*field;
            const glm::dvec3 after = sample_camera_path(keys, t + h).*field;
            const glm::dvec3 v_in = (at - before) / h;
            const glm::dvec3 v_out = (after - at) / h;
            EXPECT_LT(glm::length(v_out - v_in), 1e-3 * std::max(1.0, glm::length(v_in))) << i;
        }
    }
}

TEST(sample_camera_path, starts_towards_the_second_key) {
    // The reflected phantom key makes the first tangent point straight at key 1.
    const auto keys = winding_path();
    const glm::dvec3 v = (sample_camera_path(keys, 1e-6).position - keys[0].position) / 1e-6;
    const glm::dvec3 chord = glm::normalize(keys[1].position - keys[0].position);
    EXPECT_NEAR(glm::dot(glm::normalize(v), chord), 1.0, 1e-6);
}

TEST(sample_camera_path, collinear_keys_stay_on_their_line) {
    const glm::dvec3 origin(5.0, 1.0, -3.0);
    const glm::dvec3 direction = glm::normalize(glm::dvec3(1.0, 0.2, -2.0));
    std::vector<camera_keyframe> keys;
    const double distances[] = {0.0, 1.0, 7.0, 8.0, 30.0};
    const double times[] = {0.0, 0.5, 1.0, 4.0, 5.0};
    for (int i = 0; i < 5; ++i) {
        keys.push_back({times[i], origin + distances[i] * direction,
                        origin + (distances[i] + 10.0) * direction, 50.0f});
    }
    for (double t = 0.0; t <= 5.0; t += 0.01) {
        const camera_pose p = sample_camera_path(keys, t);
        for (glm::dvec3 q : {p.position, p.target}) {
            const glm::dvec3 off = q - origin;
            EXPECT_LT(glm::length(off - glm::dot(off, direction) * direction), 1e-9) << t;
        }
    }
}

TEST(sample_camera_path, a_metre_a_million_metres_out_has_no_jitter) {
    // Two keys 1 m apart at ~1e6 m: the path is the straight segment at constant speed, and
    // double precision keeps it monotone and within 1e-6 m of the exact point.
    const glm::dvec3 start(1.0e6, 250.0, -1.0e6);
    const glm::dvec3 end = start + glm::dvec3(1.0, 0.0, 0.0);
    const std::vector<camera_keyframe> keys = {
        {10.0, start, start + glm::dvec3(0.0, 0.0, -5.0), 50.0f},
        {11.0, end, end + glm::dvec3(0.0, 0.0, -5.0), 50.0f}};
    double previous_x = start.x;
    for (int i = 1; i <= 1000; ++i) {
        const double u = i / 1000.0;
        const camera_pose p = sample_camera_path(keys, 10.0 + u);
        EXPECT_GT(p.position.x, previous_x) << i;
        EXPECT_NEAR(p.position.x, start.x + u, 1e-6) << i;
        EXPECT_NEAR(p.position.y, start.y, 1e-6) << i;
        EXPECT_NEAR(p.position.z, start.z, 1e-6) << i;
        previous_x = p.position.x;
    }
}

}  // namespace
}  // namespace sylva
