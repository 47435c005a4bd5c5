#pragma once
// The camera the hand-computed system tests share: at the origin, looking down -z, a 90° square
// field of view over 500 pixels (one pixel is 2 tan 45° / 500 = 0.004 on the image plane at 1 m),
// emplaced as the world's camera entity.
#include <numbers>

#include "ecs/world.h"
#include "systems/update_camera_system.h"

namespace sylva {

inline void emplace_origin_camera(ecs::world& world) {
    camera cam;
    cam.position = {0.0, 0.0, 0.0};
    cam.fov_y = float(std::numbers::pi / 2.0);
    cam.aspect = 1.0f;
    cam.viewport_height_px = 500.0f;
    cam.far_plane = 1e5f;
    derive_camera_matrices(cam);
    world.emplace<camera>(world.create(), cam);
}

}  // namespace sylva
