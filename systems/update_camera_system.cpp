#include "systems/update_camera_system.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace sylva {

void derive_camera_matrices(camera& cam) {
    glm::vec3 forward = glm::normalize(cam.forward);
    glm::vec3 up = std::abs(forward.y) > 0.999f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    cam.forward = forward;
    cam.up = up;
    cam.view = glm::lookAt(glm::vec3(0.0f), forward, up);
    cam.projection = glm::perspective(cam.fov_y, cam.aspect, cam.near_plane, cam.far_plane);
    cam.pixels_per_radian = cam.viewport_height_px / cam.fov_y;
}

void update_camera_system::run(ecs::system_context<update_camera_system>& ctx) {
    camera& cam = ctx.single_mut<camera>();
    const auto& track = ctx.resource<camera_track>();
    if (track.follow && !track.keys.empty()) {
        const camera_pose pose = sample_camera_path(track.keys, ctx.resource<playback_clock>().time_s());
        cam.position = pose.position;
        const glm::dvec3 look = pose.target - pose.position;
        if (glm::length(look) > 1e-9) cam.forward = glm::vec3(glm::normalize(look));
        cam.fov_y = glm::radians(pose.fov_deg);
    }
    derive_camera_matrices(cam);
}

}  // namespace sylva
