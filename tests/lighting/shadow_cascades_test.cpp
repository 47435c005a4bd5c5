#include "lighting/shadow_cascades.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <vector>

namespace sylva {
namespace {

constexpr float k_fov = 0.9599311f;  // 55 degrees
constexpr float k_aspect = 16.0f / 9.0f;
constexpr float k_near = 0.3f;
constexpr float k_shadow_far = 400.0f;
constexpr int k_resolution = 2048;
constexpr float k_extension = 150.0f;

glm::mat4 camera_view(glm::vec3 forward) {
    const glm::vec3 f = glm::normalize(forward);
    const glm::vec3 up =
        std::abs(f.y) > 0.999f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::lookAt(glm::vec3(0.0f), f, up);
}

// The 8 corners of the view-space frustum slice between distances n and f, camera-relative.
std::vector<glm::vec3> slice_corners(const glm::mat4& view, float n, float f) {
    const glm::mat4 inverse_view = glm::inverse(view);
    const float t = std::tan(0.5f * k_fov);
    std::vector<glm::vec3> out;
    for (float d : {n, f})
        for (float sx : {-1.0f, 1.0f})
            for (float sy : {-1.0f, 1.0f})
                out.emplace_back(inverse_view *
                                 glm::vec4(sx * d * t * k_aspect, sy * d * t, -d, 1.0f));
    return out;
}

glm::vec3 to_clip(const glm::mat4& m, glm::vec3 p) {
    const glm::vec4 c = m * glm::vec4(p, 1.0f);
    return glm::vec3(c) / c.w;
}

// Shadow-map texel coordinates (0..resolution) of a camera-relative point.
glm::dvec2 texel_of(const glm::mat4& m, glm::vec3 p) {
    const glm::vec3 c = to_clip(m, p);
    return (glm::dvec2(c.x, c.y) + 1.0) * 0.5 * double(k_resolution);
}

TEST(practical_splits, matches_hand_values) {
    // n = 1, f = 1000, m = 3, lambda = 0.5: log splits 10, 100; uniform 334, 667.
    auto c = practical_splits(1.0f, 1000.0f, 3, 0.5f);
    EXPECT_FLOAT_EQ(c[0], 1.0f);
    EXPECT_FLOAT_EQ(c[1], 172.0f);
    EXPECT_FLOAT_EQ(c[2], 383.5f);
    EXPECT_FLOAT_EQ(c[3], 1000.0f);
    EXPECT_FLOAT_EQ(c[4], 1000.0f);               // past count: repeats far
    c = practical_splits(1.0f, 101.0f, 4, 0.0f);  // uniform
    for (int i = 0; i <= 4; ++i) EXPECT_FLOAT_EQ(c[std::size_t(i)], 1.0f + 25.0f * float(i));
    c = practical_splits(1.0f, 10000.0f, 4, 1.0f);  // logarithmic
    for (int i = 0; i <= 4; ++i)
        EXPECT_NEAR(c[std::size_t(i)], std::pow(10.0f, float(i)),
                    1e-3f * std::pow(10.0f, float(i)));
}

TEST(practical_splits, increase_for_any_lambda) {
    for (float lambda : {0.0f, 0.3f, 0.75f, 1.0f}) {
        const auto c = practical_splits(0.3f, 400.0f, 4, lambda);
        for (std::size_t i = 0; i < 4; ++i) EXPECT_LT(c[i], c[i + 1]) << lambda;
    }
}

TEST(sub_frustum_sphere, matches_hand_values) {
    // fov 90, aspect 1: k^2 = 2; n = 1, f = 3: c = (n+f)(1+k^2)/2 = 6 > f, so c = 3, r = 3 sqrt 2.
    frustum_sphere s = sub_frustum_sphere(glm::radians(90.0f), 1.0f, 1.0f, 3.0f);
    EXPECT_NEAR(s.center_distance, 3.0f, 1e-5f);
    EXPECT_NEAR(s.radius, 4.2426407f, 1e-5f);
    // fov 20, aspect 1.5: k^2 = tan^2(10 deg)(1 + 2.25) = 0.1010464; n = 10, f = 100:
    // c = 55 * 1.1010464 = 60.557553, r = sqrt((100 - c)^2 + k^2 f^2) = 50.657386.
    s = sub_frustum_sphere(glm::radians(20.0f), 1.5f, 10.0f, 100.0f);
    EXPECT_NEAR(s.center_distance, 60.557553f, 1e-3f);
    EXPECT_NEAR(s.radius, 50.657386f, 1e-3f);
}

TEST(fit_cascades, every_slice_corner_projects_inside_its_cascade) {
    const std::vector<glm::vec3> forwards = {
        {0, 0, -1}, {1, -0.3f, 0.2f}, {-0.4f, 0.9f, 0.1f}, {0, -1, 0}};
    const std::vector<glm::vec3> suns = {{0.3f, 0.8f, 0.4f}, {0, 1, 0}, {-0.9f, 0.05f, 0.1f}};
    for (glm::vec3 forward : forwards) {
        for (glm::vec3 sun : suns) {
            const glm::mat4 view = camera_view(forward);
            const cascade_set set =
                fit_cascades(view, k_fov, k_aspect, k_near, k_shadow_far, glm::normalize(sun), 4,
                             0.75f, k_resolution, k_extension, {123.4, 56.7, -890.1});
            ASSERT_EQ(set.count, 4);
            float previous_split = k_near;
            for (std::size_t i = 0; i < 4; ++i) {
                EXPECT_GT(set.split_far[i], previous_split);
                for (glm::vec3 p : slice_corners(view, previous_split, set.split_far[i])) {
                    const glm::vec3 c = to_clip(set.light_view_projection[i], p);
                    for (int a = 0; a < 3; ++a) {
                        EXPECT_GE(c[a], -1.0f) << i << " axis " << a;
                        EXPECT_LE(c[a], 1.0f) << i << " axis " << a;
                    }
                }
                previous_split = set.split_far[i];
            }
            EXPECT_FLOAT_EQ(set.split_far[3], k_shadow_far);
        }
    }
}

TEST(fit_cascades, texel_size_is_the_padded_sphere_diameter_over_resolution) {
    // half width = r * res / (res - 2): the sphere plus one texel each side (shadow_cascades.h).
    const glm::mat4 view = camera_view({0.2f, -0.1f, -1.0f});
    const cascade_set set = fit_cascades(view, k_fov, k_aspect, k_near, k_shadow_far,
                                         glm::normalize(glm::vec3(0.3f, 0.8f, 0.4f)), 3, 0.5f,
                                         k_resolution, k_extension);
    const auto splits = practical_splits(k_near, k_shadow_far, 3, 0.5f);
    for (std::size_t i = 0; i < 3; ++i) {
        const float r = sub_frustum_sphere(k_fov, k_aspect, splits[i], splits[i + 1]).radius;
        EXPECT_FLOAT_EQ(set.texel_world_size[i], 2.0f * r / float(k_resolution - 2));
    }
}

TEST(fit_cascades, texel_size_does_not_change_when_the_camera_turns) {
    const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 0.8f, 0.4f));
    const cascade_set a = fit_cascades(camera_view({0, 0, -1}), k_fov, k_aspect, k_near,
                                       k_shadow_far, sun, 4, 0.75f, k_resolution, k_extension);
    const cascade_set b = fit_cascades(camera_view({0.7f, -0.2f, 0.5f}), k_fov, k_aspect, k_near,
                                       k_shadow_far, sun, 4, 0.75f, k_resolution, k_extension);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(a.texel_world_size[i], b.texel_world_size[i]);
}

TEST(fit_cascades, world_origin_sits_on_a_texel_corner) {
    // The eye is at e; the world origin is at -e camera-relative. Its texel coordinates must be
    // whole numbers in every cascade, whatever sub-texel position the camera has.
    const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 0.8f, 0.4f));
    const glm::mat4 view = camera_view({0.3f, -0.2f, -1.0f});
    for (glm::dvec3 eye : {glm::dvec3(3.31, 1.7, -2.2), glm::dvec3(3.3137, 1.7, -2.2049)}) {
        const cascade_set set = fit_cascades(view, k_fov, k_aspect, k_near, 60.0f, sun, 4, 0.75f,
                                             k_resolution, k_extension, eye);
        for (std::size_t i = 0; i < 4; ++i) {
            const glm::dvec2 t = texel_of(set.light_view_projection[i], -glm::vec3(eye));
            EXPECT_NEAR(t.x, std::round(t.x), 2e-2) << i;
            EXPECT_NEAR(t.y, std::round(t.y), 2e-2) << i;
        }
    }
}

TEST(fit_cascades, moving_the_camera_a_fraction_of_a_texel_moves_the_grid_by_whole_texels) {
    // Far from the world origin, as scenarios with a world offset are: only camera-relative
    // values ever reach float. A fixed world point p seen from two nearby eyes keeps its
    // fractional texel position.
    const glm::vec3 sun = glm::normalize(glm::vec3(-0.5f, 0.6f, 0.3f));
    const glm::mat4 view = camera_view({0.1f, -0.3f, -1.0f});
    const glm::dvec3 eye0(1.0e6 + 0.123, 35.0, -2.0e6 + 0.456);
    const cascade_set set0 = fit_cascades(view, k_fov, k_aspect, k_near, k_shadow_far, sun, 4,
                                          0.75f, k_resolution, k_extension, eye0);
    for (double step : {0.0037, 0.011, 0.26}) {
        const glm::dvec3 eye1 = eye0 + glm::dvec3(step, 0.3 * step, -0.7 * step);
        const cascade_set set1 = fit_cascades(view, k_fov, k_aspect, k_near, k_shadow_far, sun, 4,
                                              0.75f, k_resolution, k_extension, eye1);
        const glm::dvec3 p = eye0 + glm::dvec3(2.5, -1.0, -6.0);
        for (std::size_t i = 0; i < 4; ++i) {
            const glm::dvec2 t0 = texel_of(set0.light_view_projection[i], glm::vec3(p - eye0));
            const glm::dvec2 t1 = texel_of(set1.light_view_projection[i], glm::vec3(p - eye1));
            const glm::dvec2 moved = t1 - t0;
            EXPECT_NEAR(moved.x, std::round(moved.x), 2e-2) << i << " step " << step;
            EXPECT_NEAR(moved.y, std::round(moved.y), 2e-2) << i << " step " << step;
        }
    }
}

TEST(fit_cascades, depth_range_reaches_caster_extension_towards_the_sun) {
    const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 0.8f, 0.4f));
    const glm::mat4 view = camera_view({0, 0, -1});
    const cascade_set set = fit_cascades(view, k_fov, k_aspect, k_near, 100.0f, sun, 1, 0.5f,
                                         k_resolution, k_extension);
    const frustum_sphere s = sub_frustum_sphere(k_fov, k_aspect, k_near, 100.0f);
    const glm::vec3 center(0.0f, 0.0f, -s.center_distance);
    const glm::mat4& m = set.light_view_projection[0];
    // Near plane (-1) is r + extension towards the sun from the centre; far (+1) is r away from it.
    EXPECT_NEAR(to_clip(m, center + sun * (s.radius + k_extension)).z, -1.0f, 1e-4f);
    EXPECT_NEAR(to_clip(m, center - sun * s.radius).z, 1.0f, 1e-4f);
    EXPECT_LT(to_clip(m, center + sun * (s.radius + k_extension + 5.0f)).z, -1.0f);
}

TEST(fit_cascades, no_cascades_gives_an_empty_set) {
    const cascade_set set =
        fit_cascades(camera_view({0, 0, -1}), k_fov, k_aspect, k_near, k_shadow_far, {0, 1, 0}, 0,
                     0.5f, k_resolution, k_extension);
    EXPECT_EQ(set.count, 0);
}

}  // namespace
}  // namespace sylva
