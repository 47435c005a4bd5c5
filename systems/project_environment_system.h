#pragma once
// Projects the environment (the analytic sky, or the scenario's environment map) to 3-band
// spherical harmonics: radiance_sh for transfer vectors and, convolved with the clamped cosine,
// irradiance_sh, what every surface is lit with. Runs only when the sky changed
// (environment::sky_revision), so a static sky costs nothing per frame. A sun that only moves
// in azimuth costs a rotation (lighting/sh_rotation.h), not an integration.
#include "components/environment.h"
#include "components/sun.h"
#include "ecs/system.h"
#include "lighting/sky_model.h"

namespace sylva {

// The work of the system, on plain data: fills env.radiance_sh, env.irradiance_sh and
// env.sky_cache from `light`'s elevation and azimuth (its direction is derived from them by
// update_sun). Ignores sky_revision.
void project_environment(environment& env, const sun& light);

// The Preetham sky of `env`'s settings with the sun in `sun_direction` (what project_environment
// integrates, and what the renderer's sky background shows).
sky_model analytic_sky(const environment& env, glm::vec3 sun_direction);

// How far the environment map is turned about the vertical, in degrees of azimuth (clockwise
// from above): the scenario's map_rotation_deg plus the sun's azimuth change since the first
// keyframe. The SH projection and the renderer's sky background both turn by it.
float environment_map_turn_deg(const environment& env, const sun& light);

struct project_environment_system {
    static constexpr std::string_view k_name = "project_environment";
    static constexpr ecs::phase k_phase = ecs::phase::lighting;
    using reads = ecs::reads<sun>;
    using writes = ecs::writes<environment>;
    static void run(ecs::system_context<project_environment_system>& ctx);
};

}  // namespace sylva
