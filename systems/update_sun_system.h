#pragma once
// Moves the sun along the scenario's sun path (elevation and azimuth keyframes, linear in time)
// and marks the sky as changed when it moved, so the environment is re-projected only then.
#include "components/environment.h"
#include "components/sun.h"
#include "ecs/system.h"
#include "resources/playback.h"

namespace sylva {

// Elevation and azimuth (degrees) at `time_s`, linear between keys, clamped at the ends.
sun_keyframe_deg sample_sun_track(const sun_track& track, double time_s);

struct update_sun_system {
    static constexpr std::string_view k_name = "update_sun";
    static constexpr ecs::phase k_phase = ecs::phase::input;
    using reads = ecs::reads<playback_clock, sun_track>;
    using writes = ecs::writes<sun, environment>;
    static void run(ecs::system_context<update_sun_system>& ctx);
};

}  // namespace sylva
