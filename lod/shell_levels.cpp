#include "lod/shell_levels.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace sylva {

shell_level shell_level_at(float distance_m, float slice_height_m, float pixels_per_radian, float min_spacing_px,
                           std::uint32_t max_level, float band) {
    const double d = std::max(double(distance_m), 1e-3);
    const double lambda = std::log2(d * double(min_spacing_px) / (double(slice_height_m) * double(pixels_per_radian)));
    if (!(lambda > 0.0)) return {0, 0.0f};
    if (lambda >= double(max_level)) return {max_level, 0.0f};
    const double whole = std::floor(lambda);
    const double into = lambda - whole;
    const double b = std::clamp(double(band), 1e-6, 1.0);
    const double t = std::clamp((into - (1.0 - b)) / b, 0.0, 1.0);
    return {std::uint32_t(whole), float(t)};
}

float shell_level_distance(const glm::vec3& eye_to_point) {
    const double d = glm::length(glm::dvec3(eye_to_point));
    const double horizontal = std::hypot(double(eye_to_point.x), double(eye_to_point.z));
    if (!(d > 0.0)) return 0.0f;
    return float(d * d / std::max(horizontal, 1e-3 * d));
}

std::uint32_t shell_pyramid_levels(std::uint32_t slices) {
    if (slices == 0) return 0;
    std::uint32_t levels = 1;
    for (std::uint32_t n = slices; n > 1; n = (n + 1) / 2) ++levels;
    return levels;
}

std::uint32_t shell_slices_at_level(std::uint32_t slices, std::uint32_t level) {
    for (std::uint32_t l = 0; l < level && slices > 1; ++l) slices = (slices + 1) / 2;
    return slices;
}

float shell_slice_height(std::uint32_t j, std::uint32_t level, float merge, float slice_height_m,
                         std::uint32_t slices_at_level) {
    const float span = std::ldexp(slice_height_m, int(level));  // 2^L·h
    const float centre = (float(j) + 0.5f) * span;
    const bool paired = (j ^ 1u) < slices_at_level;
    if (!paired) return centre;
    const float pair_centre = float(2u * (j / 2u) + 1u) * span;
    return centre + merge * (pair_centre - centre);
}

}  // namespace sylva
