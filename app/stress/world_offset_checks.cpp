// World offsets (app/stress/stress_checks.h): the tiny scene and a camera path far from the
// origin behave like the same at the origin, because positions are double precision and
// rendering is camera-relative.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "app/stress/check_support.h"
#include "app/stress/stress_checks.h"
#include "components/camera.h"
#include "measure/image_metrics.h"
#include "scenarios/camera_path.h"
#include "systems/update_camera_system.h"

namespace sylva {
namespace {

using stress::row;
using stress::rows;
using stress::text;

// Share of pixels with any of R, G, B off by more than `threshold` (of 255).
double fraction_off(const image_rgba8& a, const image_rgba8& b, int threshold) {
    const std::size_t pixels = std::size_t(a.width) * a.height;
    std::size_t off = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        bool any = false;
        for (std::size_t c = 0; c < 3; ++c)
            any = any || std::abs(int(a.texels[4 * p + c]) - int(b.texels[4 * p + c])) > threshold;
        off += any ? 1 : 0;
    }
    return pixels ? double(off) / double(pixels) : 1.0;
}

// A 100 s flight circling the origin at 30-60 m, rising and falling (2,400 frames at 24 fps).
std::vector<camera_keyframe> circling_path(glm::dvec3 offset) {
    std::vector<camera_keyframe> keys;
    for (int k = 0; k <= 8; ++k) {
        const double a = 0.8 * k, radius = 30.0 + 30.0 * (k % 3) / 2.0;
        camera_keyframe key;
        key.time_s = 12.5 * k;
        key.position =
            offset + glm::dvec3(radius * std::cos(a), 4.0 + 3.0 * (k % 2), radius * std::sin(a));
        key.target = offset + glm::dvec3(5.0 * std::sin(a), 2.0, -5.0 * std::cos(a));
        key.fov_deg = 50.0f + float(k);
        keys.push_back(key);
    }
    return keys;
}

camera camera_at(const camera_pose& pose, glm::dvec3 offset) {
    camera cam;
    cam.position = pose.position - offset;
    cam.forward = glm::vec3(glm::normalize(pose.target - pose.position));
    cam.fov_y = glm::radians(pose.fov_deg);
    derive_camera_matrices(cam);
    return cam;
}

double max_abs_difference(const glm::mat4& a, const glm::mat4& b) {
    double d = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) d = std::max(d, double(std::abs(a[c][r] - b[c][r])));
    return d;
}

}  // namespace

rows check_world_offset_renders(render::gl_context& context, int threads) {
    context.make_current();
    const scenario base = stress::tiny_scenario();
    scenario_player origin_player(base, threads, &context);
    const image_rgba8 origin = stress::render_frames(origin_player);
    const stress::image_stats origin_stats = stress::stats_of(origin);
    rows out;
    for (const double offset : {1e4, 1e5, 1e6}) {
        scenario s = base;
        s.world_offset = {offset, 0.0, offset};
        scenario_player player(s, threads, &context);
        const image_rgba8 image = stress::render_frames(player);
        const double psnr = psnr_db(origin, image);
        const double off = fraction_off(origin, image, 16);
        // A blank origin would match anything: require a lit, non-uniform frame.
        const bool meaningful = origin_stats.dark < 0.5 && origin_stats.saturated < 0.5;
        out.push_back(row(text("world offset %.0e m: frame vs origin", offset),
                          text("%.1f dB, %.2f %% px", psnr, 100.0 * off), psnr,
                          "> 45 dB, < 1 % px off > 16", psnr > 45.0 && off < 0.01 && meaningful,
                          meaningful ? "" : "the origin frame is blank"));
    }
    return out;
}

rows check_camera_path_offsets() {
    constexpr int k_frames = 2400;  // 100 s at 24 fps
    const std::vector<camera_keyframe> origin_keys = circling_path(glm::dvec3(0.0));
    rows out;
    for (const double offset_m : {1e4, 1e5, 1e6}) {
        const glm::dvec3 offset{offset_m, 0.0, -offset_m};
        const std::vector<camera_keyframe> keys = circling_path(offset);
        double position_error = 0.0, view_error = 0.0;
        for (int f = 0; f <= k_frames; ++f) {
            const double t = double(f) / 24.0;
            const camera_pose at_origin = sample_camera_path(origin_keys, t);
            const camera_pose far_away = sample_camera_path(keys, t);
            position_error = std::max({position_error,
                                       glm::length(far_away.position - offset - at_origin.position),
                                       glm::length(far_away.target - offset - at_origin.target)});
            view_error = std::max(view_error, max_abs_difference(camera_at(far_away, offset).view,
                                                                 camera_at(at_origin, {}).view));
        }
        out.push_back(row(text("camera path at %.0e m, %d frames", offset_m, k_frames),
                          text("%.1e m, view %.1e", position_error, view_error), position_error,
                          "< 1e-6 m, view < 1e-6", position_error < 1e-6 && view_error < 1e-6));
    }
    return out;
}

}  // namespace sylva
