#include "lighting/sky_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <numbers>

namespace sylva {
namespace {

constexpr float k_pi = std::numbers::pi_v<float>;

sky_model sky_at(float elevation_deg, float turbidity, float azimuth_deg = 140.0f) {
    sky_model sky;
    sky.sun_direction = sun_direction_from_angles(elevation_deg, azimuth_deg);
    sky.turbidity = turbidity;
    return sky;
}

float luminance(glm::vec3 rgb) {
    return 0.2126f * rgb.x + 0.7152f * rgb.y + 0.0722f * rgb.z;
}

void expect_near_vec(glm::vec3 a, glm::vec3 b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(sun_direction_from_angles, matches_hand_values) {
    // Azimuth clockwise from north (-z): east is +x, south +z, west -x.
    expect_near_vec(sun_direction_from_angles(90.0f, 37.0f), {0.0f, 1.0f, 0.0f}, 1e-6f);
    expect_near_vec(sun_direction_from_angles(0.0f, 90.0f), {1.0f, 0.0f, 0.0f}, 1e-6f);
    expect_near_vec(sun_direction_from_angles(0.0f, 0.0f), {0.0f, 0.0f, -1.0f}, 1e-6f);
    expect_near_vec(sun_direction_from_angles(0.0f, 180.0f), {0.0f, 0.0f, 1.0f}, 1e-6f);
    expect_near_vec(sun_direction_from_angles(30.0f, 270.0f), {-0.8660254f, 0.5f, 0.0f}, 1e-6f);
}

TEST(sky_model, radiance_is_finite_and_positive_for_every_sun_and_turbidity) {
    for (float turbidity : {2.0f, 3.0f, 4.5f, 6.0f, 8.0f, 10.0f}) {
        for (float elevation = -10.0f; elevation <= 90.0f; elevation += 5.0f) {
            const sky_model sky = sky_at(elevation, turbidity);
            for (int j = 0; j <= 12; ++j) {  // includes the zenith, the horizon and the nadir
                const float theta = float(j) / 12.0f * k_pi;
                for (int i = 0; i < 8; ++i) {
                    const float phi = float(i) / 8.0f * 2.0f * k_pi;
                    const glm::vec3 d(std::sin(theta) * std::sin(phi), std::cos(theta),
                                      -std::sin(theta) * std::cos(phi));
                    const glm::vec3 l = sky.radiance(d);
                    for (int c = 0; c < 3; ++c) {
                        ASSERT_TRUE(std::isfinite(l[c])) << elevation << " " << turbidity;
                        ASSERT_GT(l[c], 0.0f) << elevation << " " << turbidity << " " << theta;
                    }
                }
            }
            const glm::vec3 towards_sun = sky.radiance(sky.sun_direction);
            EXPECT_TRUE(std::isfinite(towards_sun.x) && towards_sun.x > 0.0f);
        }
    }
}

TEST(sky_model, unusable_sun_direction_falls_back_to_overhead) {
    sky_model sky;
    sky.sun_direction = glm::vec3(0.0f);
    const glm::vec3 l = sky.radiance(glm::normalize(glm::vec3(0.3f, 0.5f, 0.1f)));
    EXPECT_TRUE(std::isfinite(l.x) && l.x > 0.0f);
    EXPECT_TRUE(std::isfinite(ground_radiance(sky).x));
}

TEST(sky_model, zenith_brightens_as_the_sun_rises) {
    const glm::vec3 zenith{0.0f, 1.0f, 0.0f};
    for (float turbidity : {2.0f, 3.0f, 6.0f, 10.0f}) {
        float previous = 0.0f;
        for (float elevation = -10.0f; elevation <= 90.0f; elevation += 10.0f) {
            const float y = luminance(sky_at(elevation, turbidity).radiance(zenith));
            EXPECT_GT(y, previous) << elevation << " " << turbidity;
            previous = y;
        }
    }
}

TEST(sky_model, mid_elevation_sky_is_of_order_one) {
    // The scale promised in sky_model.h: sky_intensity = 1 gives roughly 0.5-1.5.
    const sky_model sky = sky_at(45.0f, 3.0f);
    const float zenith = luminance(sky.radiance({0.0f, 1.0f, 0.0f}));
    const float horizon = luminance(sky.radiance(glm::normalize(glm::vec3(1.0f, 0.1f, 0.0f))));
    EXPECT_GT(zenith, 0.4f);
    EXPECT_LT(zenith, 1.6f);
    EXPECT_GT(horizon, 0.4f);
    EXPECT_LT(horizon, 1.6f);
}

TEST(sky_model, noon_zenith_is_blue_and_the_sunset_glow_is_red) {
    const glm::vec3 noon = sky_at(60.0f, 3.0f).radiance({0.0f, 1.0f, 0.0f});
    EXPECT_GT(noon.z, noon.x);
    const sky_model sunset = sky_at(1.0f, 3.0f, 270.0f);
    const glm::vec3 glow = sunset.radiance(glm::normalize(glm::vec3(-1.0f, 0.05f, 0.0f)));
    EXPECT_GT(glow.x, glow.z);
}

TEST(sky_model, sky_intensity_scales_linearly) {
    sky_model sky = sky_at(30.0f, 4.0f);
    const glm::vec3 d = glm::normalize(glm::vec3(0.2f, 0.6f, 0.4f));
    const glm::vec3 base = sky.radiance(d);
    sky.sky_intensity = 2.0f;
    expect_near_vec(sky.radiance(d), 2.0f * base, 1e-5f);
}

TEST(ground_radiance, is_albedo_times_horizontal_irradiance_over_pi) {
    // Independent quadrature (different grid) of E = integral over the sky of L cos(theta) dw.
    sky_model sky = sky_at(35.0f, 3.0f);
    glm::dvec3 e(0.0);
    constexpr int n_theta = 90;
    constexpr int n_phi = 180;
    const double d_theta = 0.5 * std::numbers::pi / n_theta;
    const double d_phi = 2.0 * std::numbers::pi / n_phi;
    for (int j = 0; j < n_theta; ++j) {
        const double theta = (j + 0.5) * d_theta;
        for (int i = 0; i < n_phi; ++i) {
            const double phi = (i + 0.5) * d_phi;
            const glm::vec3 d(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                              float(std::sin(theta) * std::sin(phi)));
            e +=
                glm::dvec3(sky.radiance(d)) * (std::cos(theta) * std::sin(theta) * d_theta * d_phi);
        }
    }
    const glm::vec3 expected = sky.ground_albedo * glm::vec3(e) / k_pi;
    const glm::vec3 ground = sky.radiance({0.0f, -1.0f, 0.0f});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ground[c], expected[c], 0.01f * expected[c]) << c;

    // The optional sun term adds albedo * E_sun * sin(elevation) / pi exactly.
    sky.sun_irradiance = glm::vec3(3.0f);
    const glm::vec3 with_sun = ground_radiance(sky);
    const float sun_part = 3.0f * std::sin(glm::radians(35.0f)) / k_pi;
    expect_near_vec(with_sun - ground, sky.ground_albedo * sun_part, 1e-5f);
}

TEST(ground_radiance, does_not_depend_on_sun_azimuth_or_call_order) {
    const glm::vec3 a = ground_radiance(sky_at(20.0f, 5.0f, 10.0f));
    const glm::vec3 b = ground_radiance(sky_at(20.0f, 5.0f, 200.0f));
    EXPECT_EQ(a, b);
}

TEST(project_sky, lights_upward_faces_more_than_downward_ones) {
    const sky_model sky = sky_at(40.0f, 3.0f);
    const sh9_rgb irradiance = irradiance_from_radiance(project_sky(sky));
    const glm::vec3 up = evaluate(irradiance, {0.0f, 1.0f, 0.0f});
    const glm::vec3 down = evaluate(irradiance, {0.0f, -1.0f, 0.0f});
    for (int c = 0; c < 3; ++c) {
        EXPECT_TRUE(std::isfinite(up[c]) && std::isfinite(down[c]));
        EXPECT_GT(up[c], down[c]);
        EXPECT_GT(down[c], 0.0f);
    }
    // The ground below is uniform, so the downward irradiance is dominated by pi * ground
    // radiance; the 9-term fit blurs in some sky (Ramamoorthi & Hanrahan: a few % on average).
    const glm::vec3 ground = sky.radiance({0.0f, -1.0f, 0.0f});
    EXPECT_NEAR(luminance(down), k_pi * luminance(ground), 0.25f * k_pi * luminance(ground));
}

TEST(sun_radiance_color, reddens_towards_the_horizon_and_sets) {
    float previous_ratio = 1e9f;
    for (float elevation : {2.0f, 5.0f, 15.0f, 30.0f, 60.0f, 90.0f}) {
        const glm::vec3 c = sun_radiance_color(glm::radians(elevation), 3.0f);
        ASSERT_GT(c.z, 0.0f) << elevation;
        const float red_over_blue = c.x / c.z;
        EXPECT_LT(red_over_blue, previous_ratio) << elevation;
        previous_ratio = red_over_blue;
    }
    EXPECT_EQ(sun_radiance_color(glm::radians(-1.0f), 3.0f), glm::vec3(0.0f));
    EXPECT_EQ(sun_radiance_color(glm::radians(-10.0f), 10.0f), glm::vec3(0.0f));
    // Normalisation: the overhead sun through a clear (T = 2) sky has luminance 1.
    EXPECT_NEAR(luminance(sun_radiance_color(k_pi / 2.0f, 2.0f)), 1.0f, 1e-5f);
    // Haze dims it.
    EXPECT_LT(luminance(sun_radiance_color(k_pi / 4.0f, 8.0f)),
              luminance(sun_radiance_color(k_pi / 4.0f, 2.0f)));
}

}  // namespace
}  // namespace sylva
