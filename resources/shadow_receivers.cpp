#include "resources/shadow_receivers.h"

#include <algorithm>
#include <cmath>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

namespace sylva {

void receiver_heights::raise(double x, double z, double r, float y) {
    if (cells == 0) return;
    auto cell = [&](double v, double lo) {
        return std::clamp(std::int64_t(std::floor((v - lo) / cell_m)), std::int64_t(0),
                          std::int64_t(cells) - 1);
    };
    for (std::int64_t row = cell(z - r, min_xz.y); row <= cell(z + r, min_xz.y); ++row)
        for (std::int64_t col = cell(x - r, min_xz.x); col <= cell(x + r, min_xz.x); ++col) {
            float& t = top[std::size_t(row) * cells + std::size_t(col)];
            t = std::max(t, y);
        }
}

float receiver_heights::highest(glm::dvec2 lo, glm::dvec2 hi) const {
    constexpr float unknown = std::numeric_limits<float>::infinity();
    if (cells == 0) return unknown;
    const double extent = cell_m * double(cells);
    if (lo.x < min_xz.x || lo.y < min_xz.y || hi.x > min_xz.x + extent || hi.y > min_xz.y + extent)
        return unknown;
    auto cell = [&](double v, double origin) {
        return std::min(std::uint32_t(std::max((v - origin) / cell_m, 0.0)), cells - 1);
    };
    float h = -std::numeric_limits<float>::infinity();
    for (std::uint32_t row = cell(lo.y, min_xz.y); row <= cell(hi.y, min_xz.y); ++row)
        for (std::uint32_t col = cell(lo.x, min_xz.x); col <= cell(hi.x, min_xz.x); ++col)
            h = std::max(h, top[std::size_t(row) * cells + col]);
    return h;
}

receiver_heights make_receiver_heights(const heightfield& field, glm::dvec3 offset,
                                       std::uint32_t cells) {
    receiver_heights r;
    if (field.resolution < 2 || cells == 0) return r;
    r.cells = cells;
    r.cell_m = field.size_m / double(cells);
    r.min_xz = glm::dvec2(offset.x, offset.z) - 0.5 * field.size_m;
    r.top.assign(std::size_t(cells) * cells, -std::numeric_limits<float>::infinity());
    // Each sample raises the cells it touches: the bilinear surface between samples stays below
    // the highest of its four corners, and a sample on a cell edge counts for both cells.
    const double spacing = field.spacing();
    for (std::uint32_t row = 0; row < field.resolution; ++row)
        for (std::uint32_t col = 0; col < field.resolution; ++col)
            r.raise(offset.x - 0.5 * field.size_m + col * spacing,
                    offset.z - 0.5 * field.size_m + row * spacing, spacing,
                    float(offset.y + field.at(col, row)));
    return r;
}

bool slice_may_hold_receivers(const receiver_heights& receivers, const camera& cam, float near,
                              float far) {
    if (receivers.cells == 0) return true;
    // The slice's corners: (±w·d, ±h·d, −d) in view space for d = near, far, turned into the
    // world by the inverse of the view's rotation (the view is camera-relative).
    const glm::mat3 to_world = glm::transpose(glm::mat3(cam.view));
    const double h = std::tan(0.5 * double(cam.fov_y)), w = h * double(cam.aspect);
    glm::dvec2 lo{std::numeric_limits<double>::infinity()},
        hi{-std::numeric_limits<double>::infinity()};
    double lowest = std::numeric_limits<double>::infinity();
    for (const double d : {double(near), double(far)})
        for (const double sx : {-1.0, 1.0})
            for (const double sy : {-1.0, 1.0}) {
                const glm::dvec3 corner =
                    cam.position + glm::dvec3(to_world * glm::vec3(float(sx * w * d),
                                                                   float(sy * h * d), float(-d)));
                lo = glm::min(lo, glm::dvec2(corner.x, corner.z));
                hi = glm::max(hi, glm::dvec2(corner.x, corner.z));
                lowest = std::min(lowest, corner.y);
            }
    return lowest <= double(receivers.highest(lo, hi));
}

}  // namespace sylva
