#include "systems/render/submit_system.h"

#include <chrono>

namespace sylva {

void submit_system::run(ecs::system_context<submit_system>& ctx) {
    auto& device = ctx.resource_mut<render_device>();
    if (!device.renderer) return;
    const camera& cam = ctx.single<camera>();
    const auto start = std::chrono::steady_clock::now();
    render::frame_view view;
    view.view_camera = &cam;
    view.sun_light = &ctx.single<sun>();
    view.sky = &ctx.single<environment>();
    view.cascades = &ctx.resource<cascade_set>();
    view.draws = &ctx.resource<draw_list>();
    view.terrain_position = glm::vec3(device.terrain_origin - cam.position);
    view.time_s = float(ctx.resource<playback_clock>().time_s());
    view.set_samples(ctx.resource<lod_policy>().points);
    if (const lodf_slots* slots = ctx.try_resource<lodf_slots>(); slots && !slots->slots.empty()) {
        view.lodf = slots;
        view.lodf_clusters = ctx.read<cluster_changes>().data();
        view.library = &ctx.resource<species_library>();
    }
    if (const shell_view* shells = ctx.try_resource<shell_view>(); shells && shells->active) {
        view.shells = shells;
        view.shell_tiles = ctx.read<shell_tile>().data();
        view.shell_tile_count = ctx.read<shell_tile>().size();
    }
    if (const auto& ground = ctx.read<ground_tile>(); ground.size() > 0) {
        view.ground_tiles = ground.data();
        view.ground_tile_count = ground.size();
    }
    view.terrain_shadows = ctx.try_resource<terrain_shadow>();
    device.renderer->render(view);
    const auto issued = std::chrono::steady_clock::now();
    frame_stats& stats = ctx.resource_mut<frame_stats>();
    stats = device.renderer->finish();
    const auto finished = std::chrono::steady_clock::now();
    stats.submit_cpu_ms = std::chrono::duration<double, std::milli>(issued - start).count();
    stats.finish_ms = std::chrono::duration<double, std::milli>(finished - issued).count();
    seen_pixels& seen = ctx.resource_mut<seen_pixels>();
    seen.measured = false;
    if (seen.wanted) {
        device.renderer->read_ids_bottom_up(seen.ids);
        if (!seen.ids.empty()) count_seen_pixels(seen.ids, ctx.resource<draw_list>(), seen);
    }
}

}  // namespace sylva
