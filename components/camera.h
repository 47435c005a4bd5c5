#pragma once
// The viewer. One entity carries it. Writer: update_camera (scenario playback or walkthrough
// input); read by cull, select_representation, lighting (shadow cascades) and submission.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace sylva {

struct camera {
    glm::dvec3 position{0.0, 2.0, 0.0};  // world, double precision
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_y = 0.9599311f;  // radians (55 degrees)
    float aspect = 16.0f / 9.0f;
    float near_plane = 0.3f;
    float far_plane = 3000.0f;
    float lod_scale = 1.0f;  // multiplies every LOD switch distance
    float viewport_height_px = 540.0f;
    // Reference and brute-force renders (issue 4): every plant at full detail in every pass,
    // shadow cascades included, and no distance culling (with lod_scale set very large).
    bool full_geometry = false;
    // Derived each frame by update_camera, camera-relative (the eye is at the origin).
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    float pixels_per_radian = 1.0f;  // viewport height / fov_y, for projected sizes
};

}  // namespace sylva
