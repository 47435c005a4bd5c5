#pragma once
// Moves the camera along the scenario's spline path at the playback time (unless the viewer is
// flying it by hand) and derives its camera-relative view and projection matrices.
#include "components/camera.h"
#include "ecs/system.h"
#include "resources/playback.h"

namespace sylva {

// View (eye at the origin: rendering is camera-relative), projection and pixels_per_radian.
void derive_camera_matrices(camera& cam);

struct update_camera_system {
    static constexpr std::string_view k_name = "update_camera";
    static constexpr ecs::phase k_phase = ecs::phase::input;
    using reads = ecs::reads<playback_clock, camera_track>;
    using writes = ecs::writes<camera>;
    static void run(ecs::system_context<update_camera_system>& ctx);
};

}  // namespace sylva
