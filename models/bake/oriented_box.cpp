#include "models/bake/oriented_box.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace sylva {
namespace {

constexpr double k_pi = 3.14159265358979323846;

void validate(std::span<const glm::vec3> points) {
    if (points.empty()) throw std::invalid_argument("oriented box: no points");
    for (std::size_t i = 0; i < points.size(); ++i)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(points[i][k]))
                throw std::invalid_argument("oriented box: point " + std::to_string(i) + " has coordinate " +
                                            std::to_string(points[i][k]));
}

using matrix3 = std::array<std::array<double, 3>, 3>;

// Cyclic Jacobi rotations on a symmetric 3x3 matrix: `a` becomes diagonal (the eigenvalues) and
// the columns of `v` the eigenvectors. A fixed sweep cap; 3x3 converges in well under ten.
void jacobi_eigen(matrix3& a, matrix3& v) {
    v = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (int sweep = 0; sweep < 32; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        const double scale = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off <= 1e-30 * scale || off == 0.0) return;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0);
                const double s = t * c;
                for (int k = 0; k < 3; ++k) {  // a <- J^T a J
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
}

// Gram-Schmidt in the given order, third axis rebuilt as the cross product (right-handed).
std::array<glm::dvec3, 3> orthonormal_frame(glm::dvec3 a, glm::dvec3 b) {
    a = glm::normalize(a);
    b = glm::normalize(b - a * glm::dot(a, b));
    return {a, b, glm::cross(a, b)};
}

// Extents (max - min) of the points along three orthonormal axes.
glm::dvec3 extents_along(std::span<const glm::vec3> points, const std::array<glm::dvec3, 3>& axes) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity());
    glm::dvec3 hi(-std::numeric_limits<double>::infinity());
    for (const glm::vec3& p : points) {
        const glm::dvec3 q(p);
        for (int k = 0; k < 3; ++k) {
            const double d = glm::dot(q, axes[std::size_t(k)]);
            lo[k] = std::min(lo[k], d);
            hi[k] = std::max(hi[k], d);
        }
    }
    return hi - lo;
}

double padded_volume(glm::dvec3 extent, double pad) {
    return (extent.x + pad) * (extent.y + pad) * (extent.z + pad);
}

}  // namespace

oriented_box fit_box(std::span<const glm::vec3> points, const std::array<glm::vec3, 3>& axes) {
    validate(points);
    glm::dvec3 lo(std::numeric_limits<double>::infinity());
    glm::dvec3 hi(-std::numeric_limits<double>::infinity());
    for (const glm::vec3& p : points)
        for (int k = 0; k < 3; ++k) {
            const double d = glm::dot(glm::dvec3(p), glm::dvec3(axes[std::size_t(k)]));
            lo[k] = std::min(lo[k], d);
            hi[k] = std::max(hi[k], d);
        }
    oriented_box box;
    box.axes = axes;
    glm::dvec3 center(0.0);
    for (int k = 0; k < 3; ++k) center += glm::dvec3(axes[std::size_t(k)]) * (0.5 * (lo[k] + hi[k]));
    box.center = glm::vec3(center);
    box.half_extent = glm::vec3(0.5 * (hi - lo));
    return box;
}

oriented_box pca_box(std::span<const glm::vec3> points) {
    validate(points);
    glm::dvec3 mean(0.0);
    for (const glm::vec3& p : points) mean += glm::dvec3(p);
    mean /= double(points.size());
    matrix3 covariance{};
    for (const glm::vec3& p : points) {
        const glm::dvec3 d = glm::dvec3(p) - mean;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) covariance[std::size_t(r)][std::size_t(c)] += d[r] * d[c];
    }
    matrix3 vectors;
    jacobi_eigen(covariance, vectors);
    std::array<int, 3> order{0, 1, 2};  // largest variance first; ties keep the index order
    std::stable_sort(order.begin(), order.end(),
                     [&](int x, int y) { return covariance[std::size_t(x)][std::size_t(x)] > covariance[std::size_t(y)][std::size_t(y)]; });
    auto column = [&](int c) {
        return glm::dvec3(vectors[0][std::size_t(c)], vectors[1][std::size_t(c)], vectors[2][std::size_t(c)]);
    };
    const std::array<glm::dvec3, 3> frame = orthonormal_frame(column(order[0]), column(order[1]));
    return fit_box(points, {glm::vec3(frame[0]), glm::vec3(frame[1]), glm::vec3(frame[2])});
}

oriented_box minimum_volume_box(std::span<const glm::vec3> points, const oriented_box& initial,
                                const min_box_settings& settings) {
    validate(points);
    if (!(settings.step_degrees > 0.0f) || settings.step_degrees > 45.0f)
        throw std::invalid_argument("minimum_volume_box: step_degrees must be in (0, 45], got " +
                                    std::to_string(settings.step_degrees));
    const glm::dvec3 a0(initial.axes[0]), a1(initial.axes[1]);
    if (!(glm::length(glm::cross(a0, a1)) > 1e-6 * glm::length(a0) * glm::length(a1)))
        throw std::invalid_argument("minimum_volume_box: the initial box's first two axes are zero or parallel");
    std::array<glm::dvec3, 3> axes =
        orthonormal_frame(glm::dvec3(initial.axes[0]), glm::dvec3(initial.axes[1]));
    glm::dvec3 extent = extents_along(points, axes);
    const double pad = 1e-6 * std::max({extent.x, extent.y, extent.z, 1e-30});
    double best = padded_volume(extent, pad);
    const double step = double(settings.step_degrees) * k_pi / 180.0;
    const auto steps = int(std::ceil(90.0 / double(settings.step_degrees)));

    std::vector<double> along_i(points.size()), along_j(points.size());
    for (std::uint32_t round = 0; round < settings.max_rounds; ++round) {
        bool improved = false;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 axis_i = axes[std::size_t((k + 1) % 3)];
            const glm::dvec3 axis_j = axes[std::size_t((k + 2) % 3)];
            for (std::size_t p = 0; p < points.size(); ++p) {
                along_i[p] = glm::dot(glm::dvec3(points[p]), axis_i);
                along_j[p] = glm::dot(glm::dvec3(points[p]), axis_j);
            }
            int best_step = 0;
            for (int s = 1; s < steps; ++s) {
                const double c = std::cos(step * s), sn = std::sin(step * s);
                double lo_i = std::numeric_limits<double>::infinity(), hi_i = -lo_i, lo_j = lo_i, hi_j = -lo_i;
                for (std::size_t p = 0; p < points.size(); ++p) {
                    const double ri = c * along_i[p] + sn * along_j[p];
                    const double rj = c * along_j[p] - sn * along_i[p];
                    lo_i = std::min(lo_i, ri), hi_i = std::max(hi_i, ri);
                    lo_j = std::min(lo_j, rj), hi_j = std::max(hi_j, rj);
                }
                const double volume = (extent[k] + pad) * (hi_i - lo_i + pad) * (hi_j - lo_j + pad);
                // A relative margin, so rounding never makes the search cycle between equals.
                if (volume < best * (1.0 - 1e-9)) {
                    best = volume;
                    best_step = s;
                }
            }
            if (best_step == 0) continue;
            const double c = std::cos(step * best_step), sn = std::sin(step * best_step);
            const glm::dvec3 rotated_i = c * axis_i + sn * axis_j;
            const glm::dvec3 rotated_j = c * axis_j - sn * axis_i;
            axes[std::size_t((k + 1) % 3)] = rotated_i;
            axes[std::size_t((k + 2) % 3)] = rotated_j;
            axes = orthonormal_frame(axes[0], axes[1]);
            extent = extents_along(points, axes);
            best = padded_volume(extent, pad);
            improved = true;
        }
        if (!improved) break;
    }
    return fit_box(points, {glm::vec3(axes[0]), glm::vec3(axes[1]), glm::vec3(axes[2])});
}

oriented_box minimum_volume_box(std::span<const glm::vec3> points, const min_box_settings& settings) {
    return minimum_volume_box(points, pca_box(points), settings);
}

}  // namespace sylva
