#pragma once
// Scripted camera paths: keyframes (time, eye, look-at target, vertical field of view) and the
// pose between them. Eye and target follow centripetal Catmull-Rom splines (alpha = 0.5; Yuksel,
// Schaefer and Keyser 2011, "Parameterization and applications of Catmull-Rom curves"), which
// pass through every key without cusps or self-intersections within a segment, in double
// precision so paths a million metres from the origin do not jitter. The field of view is linear
// in time.
#include <glm/vec3.hpp>
#include <span>

namespace sylva {

struct camera_keyframe {
    double time_s = 0.0;
    glm::dvec3 position{0.0};  // world, metres
    glm::dvec3 target{0.0, 0.0, -1.0};
    float fov_deg = 55.0f;  // vertical
};

struct camera_pose {
    glm::dvec3 position{0.0};
    glm::dvec3 target{0.0, 0.0, -1.0};
    float fov_deg = 55.0f;
};

// The pose at `time_s`. Keys must be sorted by time (the scenario loader validates this).
// Before the first key and after the last the pose holds; one key gives a constant pose; no keys
// give camera_pose{}. Velocity is continuous in time across keys (see camera_path.cpp).
camera_pose sample_camera_path(std::span<const camera_keyframe> keys, double time_s);

}  // namespace sylva
