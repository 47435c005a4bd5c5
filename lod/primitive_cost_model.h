#pragma once
// What one more triangle, point or line costs to draw on this device, as a physical model of the
// primitive's size on screen (issue 18 item 3). Deussen 2002 §4.1 assumes "a separate triangle
// requires about as much time for rendering as three points" and builds its 3k threshold on it;
// where Sylva runs (llvmpipe, a CPU rasteriser) the ratios differ and depend on d'. The device
// calibration (systems/render/primitive_cost_calibration.h) measures the marginal time of a
// primitive on each of the renderer's drawing paths at two sizes; this model fits, per path,
//
//     t(pixels) = a + b · pixels        a >= 0: setup (vertex, primitive assembly) per primitive
//                                       b >= 0: raster and blend work per covered pixel
//
// and evaluates it at any d', so the costs a scene selects with are smooth in d' within a path
// and cannot wobble from one d' to the next as separate noisy measurements did (a line cost 9
// triangles at d' = 3 and 1 at d' = 4). Across a path change (soft splats drawn into the
// half-size layer from 4 px on, lines drawn as quads above 1.25 px) the cost changes as the
// renderer's work does.
//
// The pixels of one primitive on each path (the calibration draws exactly these shapes):
//   triangles        k_calibration_triangle_px² / 2 (4 px legs)
//   opaque splats    s² with s = d'·√c_p (splat_size_px)
//   soft splats      S² with S = K·s (soft_splat_size_px); the visibility pass's opaque splat,
//                    a fixed share of it, is folded into b
//   layered soft     the same S², drawn at half size into the splat layer (S >= 4 px)
//   native lines     one pixel wide: k_calibration_line_px (d' <= 1.25 px)
//   wide lines       d' · k_calibration_line_px, quads from the geometry shader
//
// Pure; the fit refuses data it cannot trust (calibration_refused), and the caller then keeps
// the paper's costs.
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "lod/point_line_lod.h"

namespace sylva {

enum class cost_path : std::uint8_t {
    triangles,
    opaque_splats,
    soft_splats,
    layered_soft_splats,
    native_lines,
    wide_lines,
    count
};
inline constexpr std::size_t k_cost_paths = std::size_t(cost_path::count);
const char* cost_path_name(cost_path p);

// The calibration's shapes: triangles with legs this long, lines this long, on screen.
inline constexpr double k_calibration_triangle_px = 4.0;
inline constexpr double k_calibration_line_px = 4.0;
// A measured marginal cost counts only when it is this many standard errors above zero.
inline constexpr double k_min_signal_to_noise = 5.0;
// Cost ratios outside [1/k, k] of a triangle are taken for a broken timer, not a device.
inline constexpr double k_max_cost_ratio = 256.0;

// Which path a point or line of quality `q` is drawn on, and how many pixels it covers there.
cost_path splat_path(const point_line_quality& q);
double splat_pixels(const point_line_quality& q);
cost_path line_path(const point_line_quality& q);
double line_pixels(const point_line_quality& q);
double triangle_pixels();

// One measurement: the marginal time of one primitive on `path` at `pixels` per primitive, in
// microseconds, with its standard error.
struct cost_sample {
    cost_path path = cost_path::triangles;
    double pixels = 0.0;
    double us = 0.0;
    double error_us = 0.0;
};

// The samples the calibration must take: each path at the sizes that pin its line down (two
// sizes apart, or one where the size cannot change), as the d' and splat style that draw them.
struct calibration_point {
    cost_path path = cost_path::triangles;
    point_line_quality quality;
    // How many times the calibration's usual count this point draws: the splat layer's frames
    // jitter by tens of milliseconds whatever they draw (on llvmpipe at d' = 2 the marginal
    // times of 64,000 splats spread 45 % around their median on a quiet machine, of 256,000
    // 8 %), so more primitives drown the jitter.
    std::uint32_t count_scale = 1;
};
std::vector<calibration_point> calibration_plan(float splat_factor);

// t = a + b·pixels per path, in microseconds.
struct cost_line {
    double a_us = 0.0;
    double b_us_per_px = 0.0;
    double at(double pixels) const { return a_us + b_us_per_px * pixels; }
};

struct primitive_cost_model {
    std::array<cost_line, k_cost_paths> paths{};

    // The costs a scene drawing points and lines of quality `q` selects with, relative to a
    // triangle (triangle = 1).
    primitive_costs costs_for(const point_line_quality& q) const;
};

struct calibration_refused : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Least-squares line per path through its samples, a and b clamped at zero (a path whose cost
// falls with size is noise: its mean then stands for every size). Throws calibration_refused,
// naming the path and the figures, when a sample is not k_min_signal_to_noise standard errors
// above zero, when a path of the plan has no sample, or when a path's cost at a planned size is
// more than k_max_cost_ratio times a triangle's or less than its inverse.
primitive_cost_model fit_cost_model(const std::vector<cost_sample>& samples, float splat_factor);

}  // namespace sylva
