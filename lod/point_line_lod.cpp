#include "lod/point_line_lod.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sylva {

double image_plane_units(double pixels, double fov_y_radians, double viewport_height_px) {
    return pixels * 2.0 * std::tan(0.5 * fov_y_radians) / viewport_height_px;
}

double projected_area(double area_m2, double distance_m) {
    // Deussen 2002 Eq. 1: A'_p = ½·A_p / r².
    return 0.5 * area_m2 / (distance_m * distance_m);
}

double fog_sample_distance(double sample_distance, double distance_m, double fog_density_per_m) {
    return sample_distance *
           std::min(std::exp(0.5 * fog_density_per_m * distance_m), k_fog_sample_growth_max);
}

double required_points(double area_m2, double distance_m, double sample_distance, double splat_factor) {
    if (!(distance_m > 0.0)) return distance_m == 0.0 ? std::numeric_limits<double>::infinity() : std::nan("");
    // Deussen 2002 Eq. 1: p = c_p·A'_p / A'_sp, A'_sp = d'² (see the header on the n_p factor).
    const double splat_area = sample_distance * sample_distance;
    return splat_factor * projected_area(area_m2, distance_m) / splat_area;
}

part_draw blend_points(double p, std::uint32_t k, std::span<const std::uint32_t> points_after,
                       const primitive_costs& costs, double importance) {
    part_draw d;
    if (std::isnan(p) || k == 0 || points_after.size() != std::size_t(k) + 1) return d;
    if (importance > 1.0) {
        // §4.3: decide at m·p; as points only, draw p.
        d = blend_points(p * importance, k, points_after, costs);
        if (d.triangles == 0) d.primitives = std::min(std::uint32_t(std::max(p, 0.0)), points_after[0]);
        return d;
    }
    const double rho = costs.points_per_triangle();  // the paper: 3
    const double two_k = 2.0 * double(k);
    // Deussen 2002 §5.3: p >= 3k → all triangles (3 = ρ, the points one triangle costs).
    if (p >= rho * double(k)) {
        d.triangles = k;
        return d;
    }
    // §5.3: p < 2k → the first p points (n_p = points_after[0] of them at most).
    if (p < two_k) {
        d.primitives = std::min(std::uint32_t(std::max(p, 0.0)), points_after[0]);
        return d;
    }
    // §5.3: 2k <= p < 3k → the first p − 2k triangles and the points of the other triangles;
    // with ρ for 3, (p − 2k) / (ρ − 2) triangles keep the cost at p points.
    const auto t = std::min(std::uint32_t((p - two_k) / (rho - 2.0)), k);
    d.triangles = t;
    d.primitives = points_after[t];
    return d;
}

part_draw select_lines(double area_m2, double length_m, double error_m, std::uint32_t n_lines, std::uint32_t k,
                       double distance_m, double sample_distance, const primitive_costs& costs, double importance,
                       double splat_factor, double dither) {
    if (importance > 1.0) {
        // §4.3: polygons while m·q > 1; as lines, the q·n_l coverage asks for.
        const part_draw d = select_lines(area_m2 * importance, length_m, error_m, n_lines, k, distance_m,
                                         sample_distance, costs, 1.0, splat_factor, dither);
        if (d.triangles > 0) return d;
        return select_lines(area_m2, length_m, error_m, n_lines, k, distance_m, sample_distance, costs, 1.0,
                            splat_factor, dither);
    }
    part_draw all_triangles{k, 0};
    if (n_lines == 0 || !(length_m > 0.0)) return all_triangles;
    if (!(distance_m > 0.0)) return distance_m == 0.0 ? all_triangles : part_draw{};
    // Deussen 2002 §5.2: ε_l / r >= d' → render the set by triangles.
    if (error_m / distance_m >= sample_distance) return all_triangles;
    // Short lines (see the header): l' = l / (2r·n_l) < d' → Eq. 1 splats at the lines' ends.
    if (length_m / (2.0 * distance_m * double(n_lines)) < sample_distance) {
        const double p = required_points(area_m2, distance_m, sample_distance, splat_factor);
        if (!(p <= 2.0 * double(n_lines))) return all_triangles;
        const auto splats = std::uint32_t(std::floor(p + dither));
        if (double(splats) * costs.point >= double(k) * costs.triangle) return all_triangles;
        return {0, std::min(splats, 2 * n_lines), true};
    }
    // Eq. 2: A'_sl = l'·d' = l·d' / (2r); q_l = A'_l / A'_sl.
    const double line_area = length_m * sample_distance / (2.0 * distance_m);
    const double q = projected_area(area_m2, distance_m) / line_area;
    if (q > 1.0) return all_triangles;
    // q ≤ 1: the first q·n_l lines (rounded to nearest), never fewer than one.
    const auto lines = std::clamp(std::uint32_t(std::round(q * double(n_lines))), 1u, n_lines);
    // Never slower than the triangles they stand for, on this device.
    if (double(lines) * costs.line >= double(k) * costs.triangle) return all_triangles;
    return {0, lines};
}

part_draw select_lines_fogged(double area_m2, double length_m, double error_m,
                              std::uint32_t n_lines, std::uint32_t k, double distance_m,
                              double sample_distance, double splat_distance,
                              const primitive_costs& costs, double importance, double splat_factor,
                              double dither) {
    const part_draw as_splats =
        select_lines(area_m2, length_m, error_m, n_lines, k, distance_m, splat_distance, costs,
                     importance, splat_factor, dither);
    if (as_splats.splats) return as_splats;
    return select_lines(area_m2, length_m, error_m, n_lines, k, distance_m, sample_distance, costs,
                        importance, splat_factor, dither);
}

double sample_dither(std::uint32_t seed, std::uint32_t part) {
    // splitmix64's finaliser over (seed, part): well mixed, the same on every platform.
    std::uint64_t z = (std::uint64_t(seed) << 8 | part) + 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return double(z >> 11) * 0x1.0p-53;
}

float splat_size_px(const point_line_quality& q) {
    return q.sample_distance_px * std::sqrt(std::max(q.splat_factor, 0.0f));
}

float soft_splat_size_px(const point_line_quality& q) {
    return k_soft_splat_footprint * splat_size_px(q);
}

float soft_splat_peak_alpha(const point_line_quality& q) {
    const double c_p = std::max(double(q.splat_factor), 1e-6);
    const double k = double(k_soft_splat_footprint);
    return float(std::min(1.0, 1.0 / (k_soft_splat_kernel_mean * k * k * c_p * c_p)));
}

}  // namespace sylva
