#include "lod/primitive_cost_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sylva {
namespace {

point_line_quality quality(float sample_distance_px, float splat_factor, splat_style splats) {
    return {sample_distance_px, splat_factor, true, splats, false};
}

std::string figures(const cost_sample& s) {
    std::ostringstream out;
    out.precision(3);
    out << cost_path_name(s.path) << " at " << s.pixels << " px: " << s.us << " ± " << s.error_us
        << " µs per primitive";
    return out.str();
}

}  // namespace

const char* cost_path_name(cost_path p) {
    switch (p) {
        case cost_path::triangles:
            return "triangles";
        case cost_path::opaque_splats:
            return "opaque splats";
        case cost_path::soft_splats:
            return "soft splats";
        case cost_path::layered_soft_splats:
            return "layered soft splats";
        case cost_path::native_lines:
            return "native lines";
        case cost_path::wide_lines:
            return "wide lines";
        case cost_path::count:
            break;
    }
    return "?";
}

cost_path splat_path(const point_line_quality& q) {
    if (q.splats == splat_style::opaque) return cost_path::opaque_splats;
    return soft_splat_size_px(q) >= k_splat_layer_min_side_px ? cost_path::layered_soft_splats
                                                              : cost_path::soft_splats;
}

double splat_pixels(const point_line_quality& q) {
    const double side =
        q.splats == splat_style::opaque ? double(splat_size_px(q)) : double(soft_splat_size_px(q));
    return side * side;
}

cost_path line_path(const point_line_quality& q) {
    return q.sample_distance_px > k_native_line_width_px ? cost_path::wide_lines
                                                         : cost_path::native_lines;
}

double line_pixels(const point_line_quality& q) {
    const double width = line_path(q) == cost_path::wide_lines ? double(q.sample_distance_px) : 1.0;
    return width * k_calibration_line_px;
}

double triangle_pixels() {
    return 0.5 * k_calibration_triangle_px * k_calibration_triangle_px;
}

std::vector<calibration_point> calibration_plan(float splat_factor) {
    // Two sizes per path, as far apart as the path reaches in practice (d' from 0.5 to 8 px):
    // soft splats are drawn directly up to k_splat_layer_min_side_px = 4 px (d' < 1.75 at
    // c_p = 1.3), into the layer beyond; lines natively up to 1.25 px. Native lines and the
    // triangles have one size.
    const float c_p = splat_factor;
    return {{cost_path::triangles, quality(1.0f, c_p, splat_style::soft)},
            {cost_path::opaque_splats, quality(1.0f, c_p, splat_style::opaque)},
            {cost_path::opaque_splats, quality(4.0f, c_p, splat_style::opaque)},
            {cost_path::soft_splats, quality(0.5f, c_p, splat_style::soft)},
            {cost_path::soft_splats, quality(1.5f, c_p, splat_style::soft)},
            {cost_path::layered_soft_splats, quality(2.0f, c_p, splat_style::soft), 4},
            {cost_path::layered_soft_splats, quality(6.0f, c_p, splat_style::soft), 4},
            {cost_path::native_lines, quality(1.0f, c_p, splat_style::soft)},
            {cost_path::wide_lines, quality(2.0f, c_p, splat_style::soft)},
            {cost_path::wide_lines, quality(8.0f, c_p, splat_style::soft)}};
}

primitive_costs primitive_cost_model::costs_for(const point_line_quality& q) const {
    const double triangle = paths[std::size_t(cost_path::triangles)].at(triangle_pixels());
    primitive_costs c;
    c.triangle = 1.0;
    c.point = paths[std::size_t(splat_path(q))].at(splat_pixels(q)) / triangle;
    c.line = paths[std::size_t(line_path(q))].at(line_pixels(q)) / triangle;
    return c;
}

primitive_cost_model fit_cost_model(const std::vector<cost_sample>& samples, float splat_factor) {
    for (const cost_sample& s : samples)
        if (!std::isfinite(s.us) || !std::isfinite(s.error_us) || s.us <= 0.0 ||
            s.us < k_min_signal_to_noise * s.error_us)
            throw calibration_refused("the marginal cost is not above the timer's noise (" +
                                      figures(s) + ")");
    primitive_cost_model model;
    for (std::size_t p = 0; p < k_cost_paths; ++p) {
        double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
        for (const cost_sample& s : samples) {
            if (std::size_t(s.path) != p) continue;
            n += 1.0;
            sx += s.pixels;
            sy += s.us;
            sxx += s.pixels * s.pixels;
            sxy += s.pixels * s.us;
        }
        if (n == 0.0) continue;
        cost_line& line = model.paths[p];
        const double spread = n * sxx - sx * sx;
        line.b_us_per_px = spread > 1e-12 ? (n * sxy - sx * sy) / spread : 0.0;
        line.a_us = (sy - line.b_us_per_px * sx) / n;
        if (line.b_us_per_px < 0.0) {  // cost falling with size: noise; the mean for every size
            line.b_us_per_px = 0.0;
            line.a_us = sy / n;
        }
        if (line.a_us < 0.0) {  // no setup cost below zero: the line through the origin
            line.a_us = 0.0;
            line.b_us_per_px = sxx > 0.0 ? sxy / sxx : 0.0;
        }
    }
    const double triangle = model.paths[std::size_t(cost_path::triangles)].at(triangle_pixels());
    for (const calibration_point& point : calibration_plan(splat_factor)) {
        const bool sampled = std::any_of(samples.begin(), samples.end(), [&](const cost_sample& s) {
            return s.path == point.path;
        });
        if (!sampled)
            throw calibration_refused(std::string("no measurement of ") +
                                      cost_path_name(point.path));
        const double pixels =
            point.path == cost_path::triangles ? triangle_pixels()
            : (point.path == cost_path::native_lines || point.path == cost_path::wide_lines)
                ? line_pixels(point.quality)
                : splat_pixels(point.quality);
        const double ratio = model.paths[std::size_t(point.path)].at(pixels) / triangle;
        if (!(ratio <= k_max_cost_ratio && ratio >= 1.0 / k_max_cost_ratio)) {
            std::ostringstream out;
            out << cost_path_name(point.path) << " at d' = " << point.quality.sample_distance_px
                << " px would cost " << ratio << " triangles: not a device, a broken timer";
            throw calibration_refused(out.str());
        }
    }
    return model;
}

}  // namespace sylva
