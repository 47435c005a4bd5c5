#pragma once
// Projects the sky (sun and analytic sky) to 3-band spherical harmonics and convolves it with
// the clamped cosine, giving the irradiance every surface is lit with. Runs only when the sky
// changed (environment::sky_revision), so a static sky costs nothing per frame.
#include "components/environment.h"
#include "components/sun.h"
#include "ecs/system.h"

namespace sylva {

struct project_environment_system {
    static constexpr std::string_view k_name = "project_environment";
    static constexpr ecs::phase k_phase = ecs::phase::lighting;
    using reads = ecs::reads<sun>;
    using writes = ecs::writes<environment>;
    static void run(ecs::system_context<project_environment_system>& ctx);
};

}  // namespace sylva
