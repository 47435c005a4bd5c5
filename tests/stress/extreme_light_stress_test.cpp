// Stress: sun and sky intensities from 0 to 1e12, the sun below the horizon, on it and at the
// zenith, turbidity at its limits: the SH environment, the sun uniforms and the images stay
// finite (a NaN reaching the framebuffer is written as black by llvmpipe).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/trigonometric.hpp>
#include <limits>

#include "../gl/gl_test_support.h"
#include "app/stress/stress_checks.h"
#include "stress_support.h"
#include "lighting/sky_model.h"
#include "lighting/spherical_harmonics.h"

namespace sylva {
namespace {

sh9_rgb irradiance(float sky_intensity, float turbidity = 3.0f) {
    sky_model sky;
    sky.sun_direction = sun_direction_from_angles(30.0f, 90.0f);
    sky.turbidity = turbidity;
    sky.sky_intensity = sky_intensity;
    return irradiance_from_radiance(project_sky(sky, 16, 32));
}

TEST(extreme_light_stress, sky_sh_stays_finite_and_linear_from_0_to_1e12) {
    const auto rows = check_extreme_sky();
    testing::expect_all_pass(rows);
    for (const stress_row& r : rows)
        if (r.check.rfind("sky SH", 0) == 0) {
            EXPECT_LT(r.value, 1e-5) << r.check;
        }
}

TEST(extreme_light_stress, hand_checked_sky_and_sun_values) {
    // No sky: exactly no light. 1e12: 1e12 times the unit sky, to float rounding.
    for (const glm::vec3 c : irradiance(0.0f).c) EXPECT_EQ(c, glm::vec3(0.0f));
    const sh9_rgb one = irradiance(1.0f), huge = irradiance(1e12f);
    EXPECT_GT(one.c[0].y, 0.0f);
    EXPECT_NEAR(huge.c[0].y / one.c[0].y, 1e12f, 1e12f * 1e-5f);
    // The sun has set once its disk (0.53 degrees) is below the horizon; overhead through a
    // clear atmosphere its luminance is normalised to about 1 (sky_model.h).
    EXPECT_EQ(sun_radiance_color(glm::radians(-1.0f), 3.0f), glm::vec3(0.0f));
    EXPECT_NEAR(sun_radiance_color(glm::radians(90.0f), 2.0f).y, 1.0f, 0.1f);
    // NaN through the API (the loader never passes one): turbidity taken as 3, no direct sun.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(irradiance(1.0f, nan).c[0], irradiance(1.0f, 3.0f).c[0]);
    EXPECT_EQ(sun_radiance_color(nan, 3.0f), glm::vec3(0.0f));
    EXPECT_EQ(sun_radiance_color(0.5f, nan), sun_radiance_color(0.5f, 3.0f));
}

TEST(extreme_light_stress, renders_at_extreme_intensities_and_sun_angles_stay_finite) {
    SYLVA_REQUIRE_GL();
    const auto rows = check_extreme_light_renders(*testing::shared_gl_context(), 2);
    ASSERT_EQ(rows.size(), 9u);
    testing::expect_all_pass(rows);
    EXPECT_EQ(testing::row_named(rows, "render sun 0, sky 0").value, 0.0);  // mean: black
}

}  // namespace
}  // namespace sylva
