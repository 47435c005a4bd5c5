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
    cascade_set& cascades = ctx.resource_mut<cascade_set>();
    cascades = fit_cascades(cam.view, cam.fov_y, cam.aspect, cam.near_plane, shadow_far,
                            s.direction, int(settings.cascades), settings.split_lambda,
                            int(settings.resolution), k_caster_extension_m, cam.position);
    if (const receiver_heights* receivers = ctx.try_resource<receiver_heights>())
        for (int c = 0; c < cascades.count; ++c)
            cascades.holds_receivers[std::size_t(c)] = slice_may_hold_receivers(
                *receivers, cam, c == 0 ? cam.near_plane : cascades.split_far[std::size_t(c) - 1],
                cascades.split_far[std::size_t(c)]);
}

}  // namespace sylva
