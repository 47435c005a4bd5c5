#include "systems/update_sun_system.h"

#include <glm/trigonometric.hpp>

#include <algorithm>

#include "lighting/sky_model.h"

namespace sylva {

sun_keyframe_deg sample_sun_track(const sun_track& track, double time_s) {
    if (track.keys.empty()) return {};
    // Written so NaN takes the first key (every comparison with NaN is false).
    if (!(time_s > track.keys.front().time_s)) return track.keys.front();
    if (time_s >= track.keys.back().time_s) return track.keys.back();
    auto next = std::upper_bound(track.keys.begin(), track.keys.end(), time_s,
                                 [](double t, const sun_keyframe_deg& k) { return t < k.time_s; });
    const auto& b = *next;
    const auto& a = *(next - 1);
    const auto t = float((time_s - a.time_s) / (b.time_s - a.time_s));
    return {time_s, a.elevation_deg + (b.elevation_deg - a.elevation_deg) * t,
            a.azimuth_deg + (b.azimuth_deg - a.azimuth_deg) * t};
}

void update_sun_system::run(ecs::system_context<update_sun_system>& ctx) {
    const auto& track = ctx.resource<sun_track>();
    const sun_keyframe_deg angles = sample_sun_track(track, ctx.resource<playback_clock>().time_s());
    sun& s = ctx.single_mut<sun>();
    environment& env = ctx.single_mut<environment>();
    const bool moved = angles.elevation_deg != s.elevation_deg || angles.azimuth_deg != s.azimuth_deg ||
                       track.intensity != s.intensity;
    if (!moved && env.sky_revision != 0) return;
    s.elevation_deg = angles.elevation_deg;
    s.azimuth_deg = angles.azimuth_deg;
    s.intensity = track.intensity;
    s.direction = sun_direction_from_angles(s.elevation_deg, s.azimuth_deg);
    s.color = sun_radiance_color(glm::radians(s.elevation_deg), env.turbidity);
    ++env.sky_revision;
}

}  // namespace sylva
