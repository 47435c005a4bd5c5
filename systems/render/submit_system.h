#pragma once
// The one GL submission system: gathers the frame's camera, sun, environment, cascades and draw
// list and hands them to the renderer; when the auto ladder wants it, counts what the frame
// showed of each plant (resources/seen_pixels.h). A main-thread system: it runs on the thread that owns
// the GL context, after every parallel system of the frame has finished.
#include "components/camera.h"
#include "components/cluster_changes.h"
#include "components/environment.h"
#include "components/ground_tile.h"
#include "components/sun.h"
#include "ecs/system.h"
#include "lighting/shadow_cascades.h"
#include "resources/draw_list.h"
#include "resources/frame_stats.h"
#include "resources/lod_policy.h"
#include "resources/lodf_slots.h"
#include "resources/playback.h"
#include "resources/seen_pixels.h"
#include "resources/terrain_shadow.h"
#include "systems/render/renderer.h"

namespace sylva {

// The renderer as an ECS resource; the player owns the renderer and sets this each run.
struct render_device {
    render::renderer* renderer = nullptr;
    glm::dvec3 terrain_origin{0.0};  // world position of the terrain mesh's origin
};

struct submit_system {
    static constexpr std::string_view k_name = "submit";
    static constexpr ecs::phase k_phase = ecs::phase::submit;
    static constexpr bool k_main_thread = true;
    using reads = ecs::reads<camera, sun, environment, cascade_set, draw_list, playback_clock,
                             lod_policy, lodf_slots, cluster_changes, species_library, shell_view,
                             shell_tile, ground_tile, terrain_shadow>;
    using writes = ecs::writes<render_device, frame_stats, seen_pixels>;
    static void run(ecs::system_context<submit_system>& ctx);
};

}  // namespace sylva
