#include "systems/fit_shadow_cascades_system.h"

#include <algorithm>

namespace sylva {

namespace {
// How far beyond a cascade, towards the sun, casters are still caught (metres): tall trees on a
// hill outside the view still shadow what is in it.
constexpr float k_caster_extension_m = 150.0f;
}  // namespace

void fit_shadow_cascades_system::run(ecs::system_context<fit_shadow_cascades_system>& ctx) {
    const camera& cam = ctx.single<camera>();
    const sun& s = ctx.single<sun>();
    const auto& settings = ctx.resource<shadow_settings>();
    if (settings.cascades == 0) {  // shadows off: nothing to fit, nothing to draw
        ctx.resource_mut<cascade_set>() = cascade_set{};
        return;
    }
    const float shadow_far = std::min(settings.max_distance_m, cam.far_plane);
    ctx.resource_mut<cascade_set>() =
        fit_cascades(cam.view, cam.fov_y, cam.aspect, cam.near_plane, shadow_far, s.direction,
                     int(settings.cascades), settings.split_lambda, int(settings.resolution),
                     k_caster_extension_m, cam.position);
}

}  // namespace sylva
