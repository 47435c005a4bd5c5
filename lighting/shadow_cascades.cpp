#include "lighting/shadow_cascades.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace sylva {

namespace {

constexpr float k_min_near = 1e-4f;
// Below this a cascade has no room for the one-texel margin on each side.
constexpr int k_min_map_resolution = 8;
// Past this the sun is too close to the world up axis to build the light basis from it.
constexpr float k_max_up_alignment = 0.999f;

// Light-space axes: x right, y up, z towards the sun (glm::lookAt's basis, the light looking
// along -sun). The basis depends only on the sun, so it stays put while the camera moves.
struct light_basis {
    glm::vec3 right;
    glm::vec3 up;
    glm::vec3 towards_sun;
};

light_basis make_light_basis(glm::vec3 sun_dir) {
    const float len = glm::length(sun_dir);
    const glm::vec3 sun = len > 0.0f ? sun_dir / len : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 up_ref = std::abs(sun.y) < k_max_up_alignment ? glm::vec3(0.0f, 1.0f, 0.0f)
                                                                  : glm::vec3(0.0f, 0.0f, -1.0f);
    const glm::vec3 forward = -sun;
    const glm::vec3 right = glm::normalize(glm::cross(forward, up_ref));
    return {right, glm::cross(right, forward), sun};
}

// Left edge of an ortho window of half-width `half` around `center` on one light axis, moved by
// less than a texel so that world-space texel boundaries stay where they were:
// left + anchor must be a whole number of texels, where `anchor` is the world origin's offset
// (the eye's world position along this axis). Only the anchor's remainder modulo a texel
// matters, taken in double so a camera a million metres from the origin snaps as exactly as one
// next to it (Valient 2008: round the projection's origin to texel increments).
double snapped_left_edge(double center, double half, double texel, double anchor) {
    const double anchor_remainder = anchor - texel * std::floor(anchor / texel);
    const double left = center - half;
    return texel * std::round((left + anchor_remainder) / texel) - anchor_remainder;
}

// View matrix rows are the light axes; `eye` is in light-space coordinates.
glm::mat4 light_view(const light_basis& b, glm::dvec3 eye) {
    glm::mat4 v(1.0f);
    for (int c = 0; c < 3; ++c) {
        v[c][0] = b.right[c];
        v[c][1] = b.up[c];
        v[c][2] = b.towards_sun[c];
    }
    v[3] = glm::vec4(-float(eye.x), -float(eye.y), -float(eye.z), 1.0f);
    return v;
}

}  // namespace

std::array<float, k_max_cascades + 1> practical_splits(float near, float far, int count,
                                                       float lambda) {
    const int m = std::clamp(count, 1, k_max_cascades);
    const double n = std::max(near, k_min_near);
    const double f = std::max(double(far), n);
    const double l = std::clamp(double(lambda), 0.0, 1.0);
    std::array<float, k_max_cascades + 1> c{};
    c.fill(float(f));
    c[0] = float(n);
    for (int i = 1; i < m; ++i) {
        const double s = double(i) / m;
        // Zhang et al. 2006, Eq. 4: blend of the logarithmic and uniform split schemes.
        const double logarithmic = n * std::pow(f / n, s);
        const double uniform = n + (f - n) * s;
        c[std::size_t(i)] = float(l * logarithmic + (1.0 - l) * uniform);
    }
    return c;
}

frustum_sphere sub_frustum_sphere(float fov_y, float aspect, float near, float far) {
    // Corners at distance d lie k d off the view axis, k^2 = tan^2(fov/2) (1 + aspect^2). The
    // sphere through both corner rings has its centre on the axis where
    // (c - n)^2 + k^2 n^2 = (f - c)^2 + k^2 f^2, i.e. c = (n + f)(1 + k^2) / 2; when that lies
    // past the far plane the far ring alone decides: c = f, r = k f.
    const double t = std::tan(0.5 * double(fov_y));
    const double k2 = t * t * (1.0 + double(aspect) * double(aspect));
    const double n = near;
    const double f = far;
    const double c = 0.5 * (n + f) * (1.0 + k2);
    if (c >= f) return {float(f), float(f * std::sqrt(k2))};
    return {float(c), float(std::sqrt((f - c) * (f - c) + k2 * f * f))};
}

cascade_set fit_cascades(const glm::mat4& camera_view, float fov_y, float aspect, float near,
                         float shadow_far, glm::vec3 sun_dir_towards_sun, int count, float lambda,
                         int map_resolution, float caster_extension, glm::dvec3 camera_position) {
    cascade_set out;
    if (count <= 0) return out;
    out.count = std::min(count, k_max_cascades);
    const int resolution = std::max(map_resolution, k_min_map_resolution);
    const double extension = std::max(double(caster_extension), 0.0);
    const auto splits = practical_splits(near, shadow_far, out.count, lambda);
    const glm::mat4 inverse_view = glm::inverse(camera_view);
    const light_basis basis = make_light_basis(sun_dir_towards_sun);
    const glm::dvec3 anchor(glm::dot(glm::dvec3(basis.right), camera_position),
                            glm::dot(glm::dvec3(basis.up), camera_position), 0.0);
    for (std::size_t i = 0; i < std::size_t(out.count); ++i) {
        const frustum_sphere s = sub_frustum_sphere(fov_y, aspect, splits[i], splits[i + 1]);
        const glm::vec3 center(inverse_view * glm::vec4(0.0f, 0.0f, -s.center_distance, 1.0f));
        // One texel of margin on each side absorbs the snap (header).
        const double half = double(s.radius) * resolution / (resolution - 2);
        const double texel = 2.0 * half / resolution;
        const double left = snapped_left_edge(glm::dot(basis.right, center), half, texel, anchor.x);
        const double bottom = snapped_left_edge(glm::dot(basis.up, center), half, texel, anchor.y);
        const double top_towards_sun = glm::dot(basis.towards_sun, center) + s.radius + extension;
        const glm::dvec3 eye(left + half, bottom + half, top_towards_sun);
        const auto h = float(half);
        const glm::mat4 projection =
            glm::ortho(-h, h, -h, h, 0.0f, float(2.0 * s.radius + extension));
        out.light_view_projection[i] = projection * light_view(basis, eye);
        out.split_far[i] = splits[i + 1];
        out.texel_world_size[i] = float(texel);
    }
    return out;
}

cascade_bounds make_cascade_bounds(const glm::mat4& m) {
    cascade_bounds c;
    c.light_view_projection = m;
    // For an orthographic projection the rows' lengths are the clip units per metre.
    c.radius_scale = {glm::length(glm::vec3(m[0][0], m[1][0], m[2][0])),
                      glm::length(glm::vec3(m[0][1], m[1][1], m[2][1])),
                      glm::length(glm::vec3(m[0][2], m[1][2], m[2][2]))};
    return c;
}

std::array<cascade_bounds, k_max_cascades> cascade_boxes(const cascade_set& set) {
    std::array<cascade_bounds, k_max_cascades> boxes{};
    for (int c = 0; c < set.count; ++c) {
        boxes[std::size_t(c)] = make_cascade_bounds(set.light_view_projection[std::size_t(c)]);
        boxes[std::size_t(c)].holds_receivers = set.holds_receivers[std::size_t(c)];
    }
    return boxes;
}

bool sphere_overlaps_cascade(const cascade_bounds& cascade, glm::vec3 center, float radius) {
    if (!cascade.holds_receivers) return false;
    const glm::vec4 p = cascade.light_view_projection * glm::vec4(center, 1.0f);
    const glm::vec3 r = cascade.radius_scale * radius;
    return std::abs(p.x) <= 1.0f + r.x && std::abs(p.y) <= 1.0f + r.y && p.z <= 1.0f + r.z;
}

}  // namespace sylva
