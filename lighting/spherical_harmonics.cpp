#include "lighting/spherical_harmonics.h"

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <limits>
#include <numbers>

namespace sylva {

namespace {

// Sloan 2008, Appendix A2 (see the table in the header).
constexpr float k_y0 = 0.282095f;
constexpr float k_y1 = 0.488603f;
constexpr float k_y2_mixed = 1.092548f;
constexpr float k_y2_zonal = 0.315392f;
constexpr float k_y2_sectoral = 0.546274f;

// Ramamoorthi & Hanrahan 2001, Eqs. 7-9: the clamped cosine max(0, cos) in SH, per band.
constexpr float k_pi = std::numbers::pi_v<float>;
constexpr std::array<float, 3> k_clamped_cosine_band = {k_pi, 2.0f * k_pi / 3.0f, k_pi / 4.0f};
constexpr std::array<int, 9> k_band_of = {0, 1, 1, 1, 2, 2, 2, 2, 2};

using dvec3 = glm::dvec3;

// NaN carries no energy; anything larger than the policy bound is held at it (header).
double sanitise(float v) {
    if (std::isnan(v)) return 0.0;
    return double(std::clamp(v, -k_sh_max_radiance, k_sh_max_radiance));
}

float to_finite_float(double v) {
    constexpr double k_max = double(std::numeric_limits<float>::max());
    return float(std::clamp(v, -k_max, k_max));
}

// Unit direction for polar angle theta (from +y, up) and azimuth phi (from north, -z, towards
// east, +x); the same parametrisation the renderer's sky texture uses.
glm::vec3 direction_from_polar(double theta, double phi) {
    const double s = std::sin(theta);
    return glm::vec3(float(s * std::sin(phi)), float(std::cos(theta)), float(-s * std::cos(phi)));
}

}  // namespace

sh9 sh_basis(glm::vec3 unit_dir) {
    const float x = unit_dir.x;
    const float y = unit_dir.y;
    const float z = unit_dir.z;
    return {k_y0,
            k_y1 * y,
            k_y1 * z,
            k_y1 * x,
            k_y2_mixed * x * y,
            k_y2_mixed * y * z,
            k_y2_zonal * (3.0f * z * z - 1.0f),
            k_y2_mixed * x * z,
            k_y2_sectoral * (x * x - y * y)};
}

sh9_rgb project_radiance(const std::function<glm::vec3(glm::vec3)>& radiance, int samples_theta,
                         int samples_phi) {
    const int n_theta = std::max(samples_theta, 1);
    const int n_phi = std::max(samples_phi, 1);
    const double d_theta = std::numbers::pi / n_theta;
    const double d_phi = 2.0 * std::numbers::pi / n_phi;
    std::array<dvec3, 9> sum{};
    for (int j = 0; j < n_theta; ++j) {
        const double theta = (j + 0.5) * d_theta;
        // Midpoint rule on dw = sin(theta) dtheta dphi.
        const double weight = std::sin(theta) * d_theta * d_phi;
        for (int i = 0; i < n_phi; ++i) {
            const glm::vec3 dir = direction_from_polar(theta, (i + 0.5) * d_phi);
            const glm::vec3 l = radiance(dir);
            const dvec3 weighted = dvec3(sanitise(l.x), sanitise(l.y), sanitise(l.z)) * weight;
            const sh9 y = sh_basis(dir);
            for (std::size_t k = 0; k < 9; ++k) sum[k] += weighted * double(y[k]);
        }
    }
    sh9_rgb out;
    for (std::size_t k = 0; k < 9; ++k) {
        out.c[k] = glm::vec3(to_finite_float(sum[k].x), to_finite_float(sum[k].y),
                             to_finite_float(sum[k].z));
    }
    return out;
}

sh9_rgb project_directional_light(glm::vec3 unit_dir, glm::vec3 irradiance) {
    // A delta distribution picks out the basis at its direction: c_i = E Y_i(d).
    const glm::vec3 e(float(sanitise(irradiance.x)), float(sanitise(irradiance.y)),
                      float(sanitise(irradiance.z)));
    const sh9 y = sh_basis(unit_dir);
    sh9_rgb out;
    for (std::size_t k = 0; k < 9; ++k) out.c[k] = e * y[k];
    return out;
}

sh9_rgb irradiance_from_radiance(const sh9_rgb& radiance) {
    sh9_rgb out;
    for (std::size_t k = 0; k < 9; ++k) {
        const double a = k_clamped_cosine_band[std::size_t(k_band_of[k])];
        const dvec3 c = dvec3(radiance.c[k]) * a;
        out.c[k] = glm::vec3(to_finite_float(c.x), to_finite_float(c.y), to_finite_float(c.z));
    }
    return out;
}

glm::vec3 evaluate(const sh9_rgb& coefficients, glm::vec3 unit_dir) {
    const sh9 y = sh_basis(unit_dir);
    dvec3 sum(0.0);
    for (std::size_t k = 0; k < 9; ++k) sum += dvec3(coefficients.c[k]) * double(y[k]);
    return glm::vec3(to_finite_float(sum.x), to_finite_float(sum.y), to_finite_float(sum.z));
}

}  // namespace sylva
