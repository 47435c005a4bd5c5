#include "scenarios/camera_path.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>

namespace sylva {

namespace {

using glm::dvec3;

// Coincident keys give zero-length knot intervals; this keeps the divisions finite (the terms
// they divide are then zero too).
constexpr double k_min_knot_interval = 1e-12;

// Centripetal knot spacing: |b - a|^alpha with alpha = 1/2 (Yuksel et al. 2011, Eq. 2).
double knot_interval(dvec3 a, dvec3 b) {
    return std::max(std::sqrt(glm::length(b - a)), k_min_knot_interval);
}

// A key and its neighbours, with their times. At the ends the missing neighbour is the
// reflection of the inner one through the end key (in space and time), so the path leaves the
// first key heading straight for the second.
struct neighbourhood {
    dvec3 prev, cur, next;
    double dt_prev, dt_next;
};

// Velocity (metres per second) at the middle key. The direction is the centripetal Catmull-Rom
// tangent there, dC/dt = (P1-P0)/(t1-t0) - (P2-P0)/(t2-t0) + (P2-P1)/(t2-t1) (Barry-Goldman
// pyramid differentiated at t1; Yuksel et al. 2011, Sec. 3). Converting knot units to seconds
// with one factor for both sides, the two segments' knot span over their time span, makes the
// velocity the same on either side of the key, so the camera does not jolt there. When knot
// spacing is proportional to time spacing this is exactly the centripetal spline's tangent.
dvec3 key_velocity(const neighbourhood& n) {
    const double d0 = knot_interval(n.prev, n.cur);
    const double d1 = knot_interval(n.cur, n.next);
    const dvec3 tangent =
        (n.cur - n.prev) / d0 - (n.next - n.prev) / (d0 + d1) + (n.next - n.cur) / d1;
    const double seconds = std::max(n.dt_prev + n.dt_next, 1e-12);
    return tangent * ((d0 + d1) / seconds);
}

template <class Field>
neighbourhood neighbours(std::span<const camera_keyframe> keys, std::size_t i, Field field) {
    const std::size_t last = keys.size() - 1;
    neighbourhood n{};
    n.cur = field(keys[i]);
    if (i > 0) {
        n.prev = field(keys[i - 1]);
        n.dt_prev = keys[i].time_s - keys[i - 1].time_s;
    }
    if (i < last) {
        n.next = field(keys[i + 1]);
        n.dt_next = keys[i + 1].time_s - keys[i].time_s;
    }
    if (i == 0) {
        n.prev = 2.0 * n.cur - n.next;
        n.dt_prev = n.dt_next;
    }
    if (i == last) {
        n.next = 2.0 * n.cur - n.prev;
        n.dt_next = n.dt_prev;
    }
    return n;
}

// Cubic Hermite between keys i and i+1 at fraction u of the segment's duration, written as the
// start key plus an offset so the offset keeps full precision far from the origin.
template <class Field>
dvec3 interpolate(std::span<const camera_keyframe> keys, std::size_t i, double u, Field field) {
    const double duration = keys[i + 1].time_s - keys[i].time_s;
    const dvec3 p0 = field(keys[i]);
    const dvec3 m0 = key_velocity(neighbours(keys, i, field)) * duration;
    const dvec3 m1 = key_velocity(neighbours(keys, i + 1, field)) * duration;
    const double u2 = u * u;
    const double u3 = u2 * u;
    const double h10 = u3 - 2.0 * u2 + u;
    const double h01 = -2.0 * u3 + 3.0 * u2;
    const double h11 = u3 - u2;
    return p0 + (h10 * m0 + h01 * (field(keys[i + 1]) - p0) + h11 * m1);
}

camera_pose pose_of(const camera_keyframe& k) {
    return {k.position, k.target, k.fov_deg};
}

}  // namespace

camera_pose sample_camera_path(std::span<const camera_keyframe> keys, double time_s) {
    if (keys.empty()) return {};
    if (keys.size() == 1 || !(time_s > keys.front().time_s)) return pose_of(keys.front());
    if (time_s >= keys.back().time_s) return pose_of(keys.back());
    const auto after =
        std::upper_bound(keys.begin(), keys.end(), time_s,
                         [](double t, const camera_keyframe& k) { return t < k.time_s; });
    const auto i = std::size_t(after - keys.begin()) - 1;
    const double u = (time_s - keys[i].time_s) / (keys[i + 1].time_s - keys[i].time_s);
    const auto position = [](const camera_keyframe& k) { return k.position; };
    const auto target = [](const camera_keyframe& k) { return k.target; };
    const float fov = keys[i].fov_deg + (keys[i + 1].fov_deg - keys[i].fov_deg) * float(u);
    return {interpolate(keys, i, u, position), interpolate(keys, i, u, target), fov};
}

}  // namespace sylva
