// project_environment: the analytic sky integrated once per sun elevation and turned for azimuth
// changes, the environment map turned with the sun, and both radiance and irradiance filled.
#include "systems/project_environment_system.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "lighting/sh_rotation.h"
#include "lighting/sky_model.h"

namespace sylva {
namespace {

sun sun_at(float elevation_deg, float azimuth_deg) {
    sun s;
    s.elevation_deg = elevation_deg;
    s.azimuth_deg = azimuth_deg;
    s.direction = sun_direction_from_angles(elevation_deg, azimuth_deg);
    return s;
}

sh9_rgb direct_projection(const environment& env, const sun& light) {
    return project_sky(analytic_sky(env, light.direction));
}

float largest_coefficient(const std::array<glm::vec3, 9>& c) {
    float m = 0.0f;
    for (const glm::vec3& v : c) m = std::max({m, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return m;
}

TEST(project_environment, sun_at_the_reference_azimuth_projects_as_one_integration) {
    // Bit for bit what integrating the sky with the sun's own direction gives: no rotation is
    // applied when there is nothing to turn.
    environment env;
    env.reference_azimuth_deg = 135.0f;
    const sun light = sun_at(42.0f, 135.0f);
    project_environment(env, light);
    const sh9_rgb radiance = direct_projection(env, light);
    const sh9_rgb irradiance = irradiance_from_radiance(radiance);
    for (std::size_t i = 0; i < 9; ++i) {
        EXPECT_EQ(env.radiance_sh[i], radiance.c[i]) << i;
        EXPECT_EQ(env.irradiance_sh[i], irradiance.c[i]) << i;
    }
}

TEST(project_environment, azimuth_change_turns_the_last_integration_to_match_reprojection) {
    environment env;
    env.reference_azimuth_deg = 135.0f;
    project_environment(env, sun_at(30.0f, 135.0f));
    const auto integrated = env.sky_cache.radiance_sh;
    for (float azimuth : {150.0f, 200.0f, 10.0f, 359.0f}) {
        const sun light = sun_at(30.0f, azimuth);
        project_environment(env, light);
        // No new integration: the cache still holds the sky at the reference azimuth.
        EXPECT_EQ(env.sky_cache.radiance_sh, integrated);
        const sh9_rgb direct = direct_projection(env, light);
        const sh9_rgb direct_irradiance = irradiance_from_radiance(direct);
        const float tolerance = 2e-5f * largest_coefficient(direct.c);
        for (std::size_t i = 0; i < 9; ++i) {
            for (int ch = 0; ch < 3; ++ch) {
                EXPECT_NEAR(env.radiance_sh[i][ch], direct.c[i][ch], tolerance)
                    << azimuth << " " << i;
                EXPECT_NEAR(env.irradiance_sh[i][ch], direct_irradiance.c[i][ch], 4.0f * tolerance);
            }
        }
    }
}

TEST(project_environment, elevation_change_integrates_again) {
    environment env;
    env.reference_azimuth_deg = 135.0f;
    project_environment(env, sun_at(30.0f, 135.0f));
    const sun light = sun_at(55.0f, 135.0f);
    project_environment(env, light);
    EXPECT_EQ(env.sky_cache.sun_elevation_deg, 55.0f);
    const sh9_rgb direct = direct_projection(env, light);
    for (std::size_t i = 0; i < 9; ++i) EXPECT_EQ(env.radiance_sh[i], direct.c[i]) << i;
}

TEST(project_environment, result_does_not_depend_on_the_path_the_sun_took) {
    // Determinism under seeking: the projection for a sun is the same whether it came from
    // another azimuth, another elevation or nowhere.
    environment direct;
    direct.reference_azimuth_deg = 100.0f;
    project_environment(direct, sun_at(20.0f, 170.0f));
    environment travelled = direct;
    travelled.sky_cache = {};
    project_environment(travelled, sun_at(60.0f, 100.0f));
    project_environment(travelled, sun_at(20.0f, 120.0f));
    project_environment(travelled, sun_at(20.0f, 170.0f));
    EXPECT_EQ(travelled.radiance_sh, direct.radiance_sh);
    EXPECT_EQ(travelled.irradiance_sh, direct.irradiance_sh);
}

TEST(project_environment, a_map_turns_with_the_sun_and_its_own_rotation) {
    // A map lit only by a band-1 lobe towards north (-z): c2 ("z") = -1. Turning it 90 degrees
    // in azimuth (north -> east) must give the same lobe towards east (+x): c3 ("x") = +1.
    environment env;
    env.has_map = true;
    env.reference_azimuth_deg = 135.0f;
    env.sky_intensity = 2.0f;
    env.map_radiance_sh[0] = glm::vec3(3.0f);
    env.map_radiance_sh[2] = glm::vec3(-1.0f);
    for (const auto& [map_rotation, sun_azimuth] :
         {std::pair{90.0f, 135.0f}, std::pair{0.0f, 225.0f}, std::pair{45.0f, 180.0f}}) {
        env.map_rotation_deg = map_rotation;
        project_environment(env, sun_at(40.0f, sun_azimuth));
        EXPECT_NEAR(env.radiance_sh[0].x, 6.0f, 1e-6f);  // scaled by sky_intensity
        EXPECT_NEAR(env.radiance_sh[3].x, 2.0f, 1e-5f) << map_rotation << " " << sun_azimuth;
        for (std::size_t i : {1u, 2u, 4u, 5u, 6u, 7u, 8u})
            EXPECT_NEAR(env.radiance_sh[i].x, 0.0f, 1e-5f) << i;
        EXPECT_EQ(env.irradiance_sh, irradiance_from_radiance({env.radiance_sh}).c);
    }
    EXPECT_FALSE(env.sky_cache.valid);  // the analytic sky is never integrated
}

}  // namespace
}  // namespace sylva
