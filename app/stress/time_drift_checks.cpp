// Time (app/stress/stress_checks.h): a million and ten million frames in, the clock, the camera
// path and the sun are where direct evaluation at frame / fps puts them; nothing accumulates.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "app/stress/check_support.h"
#include "app/stress/stress_checks.h"
#include "components/camera.h"
#include "components/sun.h"
#include "resources/playback.h"
#include "scenarios/camera_path.h"
#include "systems/update_camera_system.h"
#include "systems/update_sun_system.h"

namespace sylva {

using stress::row;
using stress::rows;
using stress::text;

namespace {
constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();
constexpr double k_inf = std::numeric_limits<double>::infinity();
}  // namespace

rows check_time_drift(int threads) {
    rows out;
    // The clock stepped frame by frame as the player does, against a naive accumulator.
    playback_clock clock{0, 24.0};
    double accumulated = 0.0, clock_drift = 0.0, naive_drift = 0.0;
    constexpr std::uint64_t k_frames = 10'000'000;
    for (std::uint64_t f = 0; f <= k_frames; ++f) {
        clock.frame = f;
        const double direct = double(f) / 24.0;
        clock_drift = std::max(clock_drift, std::abs(clock.time_s() - direct));
        if (f == 1'000'000 || f == k_frames)
            naive_drift = std::max(naive_drift, std::abs(accumulated - direct));
        accumulated += 1.0 / 24.0;
    }
    out.push_back(row("clock stepped to frame 1e7 (24 fps)", text("%.1e s", clock_drift),
                      clock_drift, "0 s", clock_drift == 0.0,
                      text("adding 1/24 per frame would drift %.1e s", naive_drift)));

    // A straight 1 m/s path 1e6 m out: collinear, evenly spaced keys make the centripetal spline
    // exactly linear (equal key velocities, Hermite tangents = chords), so x(t) = t.
    const glm::dvec3 offset{1e6, 0.0, 1e6};
    std::vector<camera_keyframe> line;
    for (int k = 0; k <= 5; ++k) {
        const double t = 2e5 * k;
        line.push_back(
            {t, offset + glm::dvec3(t, 10.0, 0.0), offset + glm::dvec3(t + 50.0, 8.0, 0.0), 55.0f});
    }
    double position_error = 0.0, step_error = 0.0;
    for (const std::uint64_t start : {1'000'000ULL, 10'000'000ULL, 23'999'000ULL})
        for (std::uint64_t f = start; f < start + 1000; ++f) {
            const double t = double(f) / 24.0;
            const double x = sample_camera_path(line, t).position.x - offset.x;
            const double next =
                sample_camera_path(line, double(f + 1) / 24.0).position.x - offset.x;
            position_error = std::max(position_error, std::abs(x - t));
            step_error = std::max(step_error, std::abs((next - x) * 24.0 - 1.0));
        }
    out.push_back(
        row("1 m/s path at 1e6 m, frames 1e6..2.4e7",
            text("%.1e m, step %.1e", position_error, step_error), position_error,
            "< 1e-6 m, step +- 1e-6", position_error < 1e-6 && step_error < 1e-6,
            "x(frame / 24) against frame / 24 m; step: (x(f+1) - x(f)) x 24 against 1 m/s"));

    // The sun from -10 to 80 degrees over 1e6 s: linear, monotone frame to frame.
    sun_track track;
    track.keys = {{0.0, -10.0f, 90.0f}, {1e6, 80.0f, 270.0f}};
    double elevation_error = 0.0;
    bool monotone = true;
    float previous = -1e9f;
    for (std::uint64_t f = 10'000'000; f < 10'001'000; ++f) {
        const double t = double(f) / 24.0;
        const float e = sample_sun_track(track, t).elevation_deg;
        elevation_error = std::max(elevation_error, std::abs(double(e) - (-10.0 + 90.0 * t / 1e6)));
        monotone = monotone && e >= previous;
        previous = e;
    }
    out.push_back(row("sun path at frame 1e7", text("%.1e deg", elevation_error), elevation_error,
                      "< 1e-4 deg, monotone", elevation_error < 1e-4 && monotone));

    // Beyond the last key the pose holds; a NaN or infinite time never reaches the spline.
    const scenario s = stress::tiny_scenario();
    std::vector<camera_keyframe> keys;
    for (const auto& k : s.camera.keyframes) keys.push_back(k.key);
    bool holds = true;
    for (const double t : {keys.back().time_s + 1e-9, 1e6 / 24.0, 1e7 / 24.0, k_inf})
        holds = holds && sample_camera_path(keys, t).position == keys.back().position;
    for (const double t : {-1.0, -k_inf, k_nan})
        holds = holds && sample_camera_path(keys, t).position == keys.front().position;
    out.push_back(stress::yes_no_row("camera path past its last key", holds, "holds last key", "moves",
                                     "last key; NaN, < 0: first key"));

    // The whole frame at frames 1e6 and 1e7: camera and sun equal direct evaluation.
    scenario long_play = s;
    long_play.sun.keyframes = {{0.0, 10.0f, 90.0f}, {1e6, 60.0f, 180.0f}};
    scenario_player player(long_play, threads, nullptr);
    bool exact = true;
    for (const std::uint64_t f : {1'000'000ULL, 10'000'000ULL}) {
        player.set_frame(f);
        player.step();
        const double t = double(f) / long_play.fps;
        const auto& track_keys = player.world().resource<camera_track>().keys;
        exact = exact && player.world().single<camera>().position ==
                             sample_camera_path(track_keys, t).position;
        exact =
            exact && player.world().single<sun>().elevation_deg ==
                         sample_sun_track(player.world().resource<sun_track>(), t).elevation_deg;
    }
    out.push_back(stress::yes_no_row("player at frames 1e6, 1e7", exact, "camera, sun exact", "differ",
                                     "== path(frame / fps)"));
    return out;
}

}  // namespace sylva
