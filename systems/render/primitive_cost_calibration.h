#pragma once
// Measures what one more triangle, point or line costs on this GL device (issue 5 item 6; made
// robust by issue 18 item 3) and fits the physical model of lod/primitive_cost_model.h.
//
// For each point of the model's calibration plan (a drawing path at a size), the calibration
// draws N and then 2N leaf-sized primitives of that kind through the renderer's own passes (the
// programs every frame uses; soft splats with their visibility pass, through the splat layer
// from 4 px on) in front of a camera like a scene's, and takes the difference: the marginal
// time of N primitives, free of everything a frame costs whatever it draws. N starts small and
// is chosen so that difference is well above the frame's own jitter. The repetitions then
// interleave the plan points, N and 2N alternating which goes first, so a machine that slows
// down over the calibration slows every point alike, until each point's standard error is small;
// each point's cost is the median of its repetitions, with the median's standard error, and the
// fit refuses points whose cost is not clearly above that error (calibration_refused): the
// caller then keeps the paper's costs.
//
// What a frame costs is measured up to glFinish, and on a CPU rasteriser (llvmpipe, softpipe)
// as the CPU time of the whole process: the device is the CPU, and a primitive costs the time
// every thread (the one issuing GL calls, where llvmpipe shades vertices, and its rasteriser
// threads) spends on it. Unlike wall-clock time it does not count the time the process waits
// for a core another program holds, so a busy machine calibrates like an idle one: with the
// machine's other core loaded, per-primitive times by wall clock came out 1.6-2x larger and
// with 2-4x the spread of the same run's CPU times. Elsewhere (a GPU) it is wall-clock time.
// GPU timer queries are not used: llvmpipe's miss the vertex work done while calls are issued.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lod/primitive_cost_model.h"
#include "systems/render/renderer.h"

namespace sylva::render {

// Where the calibration primitives float, in front of the eye.
inline constexpr float k_calibration_distance_m = 20.0f;

// `count` primitives of one kind scattered over the middle of the view at
// k_calibration_distance_m, as leaf samples (the leaf texture's opaque centre), facing the eye:
// triangles with legs of `triangle_leg_px`, lines k_calibration_line_px long (`pixel_m`: metres
// per pixel there).
mesh_data calibration_mesh(primitive_kind kind, std::uint32_t count, float pixel_m, float half_width_m,
                           float half_height_m, double triangle_leg_px = k_calibration_triangle_px);

// What a calibration frame draws with: the eye (at the origin, looking down -z, at the
// renderer's frame size), the metres per pixel at k_calibration_distance_m and the half extents
// the primitives are scattered over there, a sun, a sky, no cascades (a calibration that times
// the shadow pass sets one), one draw list, and `view` wired to all of them with the terrain far
// out of sight. Not copyable: `view` points into it.
struct calibration_scene {
    camera cam;
    float pixel_m = 0.0f;
    float half_width_m = 0.0f;
    float half_height_m = 0.0f;
    sun light;
    environment sky;
    cascade_set cascades;
    draw_list list;
    frame_view view;

    explicit calibration_scene(const renderer& r);
    calibration_scene(const calibration_scene&) = delete;
    calibration_scene& operator=(const calibration_scene&) = delete;
};

// Median of the repetitions and the median's standard error (1.2533 σ/√n, σ from the median
// absolute deviation: robust to the odd frame a busy machine stretches). {0, 0} when empty.
std::pair<double, double> median_and_error(std::vector<double> v);

// One frame the calibration times: `count` primitives on `path`, drawn at `quality`.
struct calibration_frame {
    cost_path path = cost_path::triangles;
    point_line_quality quality;
    std::uint32_t count = 0;
    // The shader-work calibration's shape (shader_work_calibration.h: 0 small triangles in the
    // view, 1 large ones, 2 large ones into a shadow map, 3 tiny ones in the view); 0 in the
    // primitive calibration.
    std::uint32_t shape = 0;
};

// Runs `draw` (which renders the frame and waits for it) and returns how long it took, in ms.
// Tests inject a broken one to see the calibration refuse it.
using frame_timer =
    std::function<double(const calibration_frame&, const std::function<void()>& draw)>;
double wall_clock_ms(const calibration_frame& frame, const std::function<void()>& draw);
double process_cpu_ms(const calibration_frame& frame, const std::function<void()>& draw);
// process_cpu_ms on a CPU rasteriser (by its GL_RENDERER string), wall_clock_ms elsewhere.
frame_timer device_frame_timer(const std::string& gl_renderer);

struct calibration_settings {
    float splat_factor = 1.3f;          // c_p the splats are sized with
    // N of every plan point: first_count, doubled while 2N costs less than min_marginal_ms more
    // than N (a fast device). One N for every path where the device allows it: the marginal
    // cost of a primitive depends a little on how many are drawn (caches, binning), so a count
    // that changed from run to run would move the costs with it.
    std::uint32_t first_count = 64000;
    std::uint32_t max_count = 1024000;  // 2N never exceeds it (the meshes hold this many)
    double min_marginal_ms = 15.0;
    // Repetitions of each plan point: at least the first, then more for a point until its
    // standard error is below target_relative_error of its cost, or the most are done.
    int min_repetitions = 9;
    int max_repetitions = 31;
    double target_relative_error = 0.02;
    frame_timer timer;  // empty: process_cpu_ms (device_cost_model picks the device's)
};

// How both calibrations time their plan points. For point i, N is a power of two times
// first_count · count_scales[i] at which 2N costs min_marginal_ms more than N, extrapolated from
// the marginal time at the first N (after a frame that compiles the point's programs and touches
// its buffers; the median of three differences decides, so one stretched frame does not mislead
// it). Then repetitions interleave the points not yet settled (standard error under
// target_relative_error of the marginal time), in a different order each time, N and 2N
// alternating which goes first: drift over the calibration weighs on every point alike.
// `time(i, n)` draws point i with n primitives and returns how long it took, in ms.
struct marginal_timings {
    std::vector<std::uint32_t> counts;            // N per point
    std::vector<std::vector<double>> marginal_ms;  // per point, 2N less N, one per repetition
};
marginal_timings time_marginals(const std::vector<std::uint32_t>& count_scales,
                                const std::function<double(std::size_t, std::uint32_t)>& time,
                                const calibration_settings& settings);

struct calibration_result {
    std::optional<primitive_cost_model> model;  // none when the fit refused the samples
    std::string refusal;                        // why
    std::vector<cost_sample> samples;           // one per plan point
    std::vector<std::uint32_t> counts;          // N of each
    double seconds = 0.0;
};

// Adds its three meshes to the renderer's pool, renders into the renderer's target (overwriting
// its last image) and returns the samples and the fitted model, or the reason the fit refused
// them (calibration_refused: timings that cannot be trusted). GL thread only.
calibration_result calibrate_primitive_costs(renderer& r,
                                             const calibration_settings& settings = {});

}  // namespace sylva::render
