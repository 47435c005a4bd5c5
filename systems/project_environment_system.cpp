#include "systems/project_environment_system.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lighting/sh_rotation.h"
#include "lighting/sky_model.h"
#include "lighting/spherical_harmonics.h"

namespace sylva {

namespace {

bool cache_matches(const sky_projection_cache& cache, const environment& env, const sun& light) {
    return cache.valid && cache.sun_elevation_deg == light.elevation_deg &&
           cache.turbidity == env.turbidity && cache.sky_intensity == env.sky_intensity &&
           cache.ground_albedo == env.ground_albedo;
}

sh9_rgb to_sh(const std::array<glm::vec3, 9>& coefficients) {
    sh9_rgb out;
    out.c = coefficients;
    return out;
}

// Turns coefficients by `delta_azimuth_deg`; no turn leaves them bit for bit (a static sun at
// the reference azimuth projects exactly as an unrotated integration). A non-finite turn
// (no scenario gives one) is taken as none.
sh9_rgb turned(const sh9_rgb& coefficients, float delta_azimuth_deg) {
    if (delta_azimuth_deg == 0.0f || !std::isfinite(delta_azimuth_deg)) return coefficients;
    return rotate(coefficients, azimuth_rotation(delta_azimuth_deg));
}

// Preetham's sky depends on the sun only through the sun's elevation and angles to it, so the
// sky for sun azimuth a is the sky for the reference azimuth turned by a - reference: integrate
// only when anything else changed.
sh9_rgb analytic_sky_radiance(environment& env, const sun& light) {
    sky_projection_cache& cache = env.sky_cache;
    if (!cache_matches(cache, env, light)) {
        const sky_model sky =
            analytic_sky(env, sun_direction_from_angles(light.elevation_deg, env.reference_azimuth_deg));
        cache = {true,
                 light.elevation_deg,
                 env.turbidity,
                 env.sky_intensity,
                 env.ground_albedo,
                 project_sky(sky).c};
    }
    return turned(to_sh(cache.radiance_sh), light.azimuth_deg - env.reference_azimuth_deg);
}

// The map as the file lies, scaled by sky_intensity and turned (environment_map_turn_deg): a
// moving sun turns the environment with it.
sh9_rgb map_radiance(const environment& env, const sun& light) {
    constexpr double k_max = double(std::numeric_limits<float>::max());
    const double scale =
        std::isnan(env.sky_intensity) ? 0.0 : std::max(double(env.sky_intensity), 0.0);
    sh9_rgb scaled;
    for (std::size_t i = 0; i < 9; ++i)
        for (int ch = 0; ch < 3; ++ch)
            scaled.c[i][ch] =
                float(std::clamp(double(env.map_radiance_sh[i][ch]) * scale, -k_max, k_max));
    return turned(scaled, environment_map_turn_deg(env, light));
}

}  // namespace

sky_model analytic_sky(const environment& env, glm::vec3 sun_direction) {
    sky_model sky;
    sky.sun_direction = sun_direction;
    sky.turbidity = env.turbidity;
    sky.sky_intensity = env.sky_intensity;
    sky.ground_albedo = env.ground_albedo;
    return sky;
}

float environment_map_turn_deg(const environment& env, const sun& light) {
    return env.map_rotation_deg + (light.azimuth_deg - env.reference_azimuth_deg);
}

void project_environment(environment& env, const sun& light) {
    const sh9_rgb radiance =
        env.has_map ? map_radiance(env, light) : analytic_sky_radiance(env, light);
    const sh9_rgb irradiance = irradiance_from_radiance(radiance);
    env.radiance_sh = radiance.c;
    env.irradiance_sh = irradiance.c;
}

void project_environment_system::run(ecs::system_context<project_environment_system>& ctx) {
    environment& env = ctx.single_mut<environment>();
    if (env.projected_revision == env.sky_revision) return;
    project_environment(env, ctx.single<sun>());
    env.projected_revision = env.sky_revision;
}

}  // namespace sylva
