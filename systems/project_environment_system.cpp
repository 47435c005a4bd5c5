#include "systems/project_environment_system.h"

#include "systems/lighting/sky_model.h"
#include "systems/lighting/spherical_harmonics.h"

namespace sylva {

void project_environment_system::run(ecs::system_context<project_environment_system>& ctx) {
    environment& env = ctx.single_mut<environment>();
    if (env.projected_revision == env.sky_revision) return;
    sky_model sky;
    sky.sun_direction = ctx.single<sun>().direction;
    sky.turbidity = env.turbidity;
    sky.sky_intensity = env.sky_intensity;
    sky.ground_albedo = env.ground_albedo;
    const sh9_rgb radiance = project_sky(sky);
    const sh9_rgb irradiance = irradiance_from_radiance(radiance);
    for (std::size_t i = 0; i < 9; ++i) {
        env.irradiance_sh[i] = irradiance.c[i];
        env.radiance_sh[i] = radiance.c[i];
    }
    env.projected_revision = env.sky_revision;
}

}  // namespace sylva
