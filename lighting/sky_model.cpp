#include "lighting/sky_model.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <numbers>

namespace sylva {

namespace {

constexpr double k_pi = std::numbers::pi;
constexpr double k_min_turbidity = 2.0;  // Preetham's fits cover T = 2..10 (clear to hazy)
constexpr double k_max_turbidity = 10.0;
constexpr double k_default_turbidity = 3.0;  // the scenario default (scenarios/scenario.h)
// Model luminance is in kcd/m^2 (about 10 at the zenith for T = 3, sun at 60 degrees); this
// brings sky_intensity = 1 to radiance of order 1.
constexpr double k_radiance_per_kcd = 0.1;
// Below the horizon the Perez fits do not apply (zenith luminance goes negative for hazy skies);
// the sky is evaluated with the sun on the horizon and dimmed by exp(elevation / 3 degrees), a
// non-physical twilight that stays positive: 3.6 % of the sunset sky at -10 degrees.
constexpr double k_twilight_scale_rad = 3.0 * k_pi / 180.0;
// Perez's 1/cos(theta) term: directions are held this far above the horizon.
constexpr double k_min_cos_view = 1e-3;
// Floor on each RGB channel relative to luminance: the xyY -> RGB matrix can give a slightly
// negative channel for saturated chromaticities; radiance must stay positive.
constexpr double k_min_channel_fraction = 1e-3;
// Ground irradiance quadrature over the upper hemisphere (theta, phi midpoints).
constexpr int k_ground_samples_theta = 32;
constexpr int k_ground_samples_phi = 64;

// Turbidity clamped to the fits' range; NaN (no scenario can give one, only a caller of this
// API) is taken as the default, so a bad input gives a plausible sky rather than NaN radiance.
double usable_turbidity(float turbidity) {
    if (std::isnan(turbidity)) return k_default_turbidity;
    return std::clamp(double(turbidity), k_min_turbidity, k_max_turbidity);
}

struct perez_coefficients {
    double a, b, c, d, e;
};

// Preetham 1999, Appendix A.2: Perez distribution coefficients as linear functions of turbidity
// for luminance Y and chromaticities x, y.
perez_coefficients perez_luminance(double t) {
    return {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771,
            -0.0670 * t + 0.3703};
}
perez_coefficients perez_x(double t) {
    return {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989,
            -0.0033 * t + 0.0452};
}
perez_coefficients perez_y(double t) {
    return {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537,
            -0.0109 * t + 0.0529};
}

// Perez et al. 1993 all-weather model as used by Preetham 1999, Eq. 3:
// F(theta, gamma) = (1 + A exp(B / cos theta)) (1 + C exp(D gamma) + E cos^2 gamma).
double perez(const perez_coefficients& p, double cos_theta, double gamma) {
    const double cos_gamma = std::cos(gamma);
    return (1.0 + p.a * std::exp(p.b / cos_theta)) *
           (1.0 + p.c * std::exp(p.d * gamma) + p.e * cos_gamma * cos_gamma);
}

// Preetham 1999, Appendix A.2: zenith luminance (kcd/m^2) from turbidity and sun zenith angle.
double zenith_luminance(double t, double theta_s) {
    const double chi = (4.0 / 9.0 - t / 120.0) * (k_pi - 2.0 * theta_s);
    return (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;
}

// Preetham 1999, Appendix A.2: zenith chromaticity as a turbidity polynomial times a cubic in
// the sun zenith angle.
double zenith_chromaticity(double t, double theta_s, const double (&m)[3][4]) {
    const double th[4] = {theta_s * theta_s * theta_s, theta_s * theta_s, theta_s, 1.0};
    const double tv[3] = {t * t, t, 1.0};
    double sum = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) sum += tv[i] * m[i][j] * th[j];
    return sum;
}
constexpr double k_zenith_x[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                     {-0.02903, 0.06377, -0.03202, 0.00394},
                                     {0.11693, -0.21196, 0.06052, 0.25886}};
constexpr double k_zenith_y[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                     {-0.04214, 0.08970, -0.04153, 0.00516},
                                     {0.15346, -0.26756, 0.06670, 0.26688}};

// xyY -> CIE XYZ -> linear sRGB (Rec. 709 primaries, D65 white); matrix from B. Lindbloom,
// "RGB/XYZ Matrices" (brucelindbloom.com), sRGB.
glm::dvec3 xyy_to_linear_srgb(double x, double y, double luminance) {
    const double big_x = x / y * luminance;
    const double big_z = (1.0 - x - y) / y * luminance;
    return {3.2404542 * big_x - 1.5371385 * luminance - 0.4985314 * big_z,
            -0.9692660 * big_x + 1.8760108 * luminance + 0.0415560 * big_z,
            0.0556434 * big_x - 0.2040259 * luminance + 1.0572252 * big_z};
}

// Everything about the sky that depends on the sun and turbidity but not on the view direction.
struct prepared_sky {
    glm::dvec3 sun;  // towards the sun, held at or above the horizon
    perez_coefficients py, px, pyc;
    double zenith_y_over_f0;  // zenith value / F(0, theta_s): Preetham 1999, Eq. 3
    double zenith_x_over_f0;
    double zenith_yc_over_f0;
    double scale;  // luminance units -> radiance, twilight and sky_intensity included
};

// The sun direction as given, normalised; straight up when it has no usable direction (zero or
// non-finite), so a bad input gives a plausible sky rather than NaN.
glm::dvec3 unit_sun(glm::vec3 sun_direction) {
    const glm::dvec3 s(sun_direction);
    const double len = glm::length(s);
    if (!std::isfinite(len) || len < 1e-12) return {0.0, 1.0, 0.0};
    return s / len;
}

glm::dvec3 sun_at_or_above_horizon(glm::vec3 sun_direction) {
    const glm::dvec3 s = unit_sun(sun_direction);
    const double horizontal = std::hypot(s.x, s.z);
    if (s.y >= 0.0) return s;
    if (horizontal < 1e-9) return {1.0, 0.0, 0.0};  // straight below: any horizon point
    return {s.x / horizontal, 0.0, s.z / horizontal};
}

prepared_sky prepare(glm::vec3 sun_direction, float turbidity, float sky_intensity) {
    const double t = usable_turbidity(turbidity);
    prepared_sky p{};
    p.sun = sun_at_or_above_horizon(sun_direction);
    const double theta_s = std::acos(std::clamp(p.sun.y, 0.0, 1.0));
    p.py = perez_luminance(t);
    p.px = perez_x(t);
    p.pyc = perez_y(t);
    p.zenith_y_over_f0 = zenith_luminance(t, theta_s) / perez(p.py, 1.0, theta_s);
    p.zenith_x_over_f0 = zenith_chromaticity(t, theta_s, k_zenith_x) / perez(p.px, 1.0, theta_s);
    p.zenith_yc_over_f0 = zenith_chromaticity(t, theta_s, k_zenith_y) / perez(p.pyc, 1.0, theta_s);
    const double elevation = std::asin(std::clamp(unit_sun(sun_direction).y, -1.0, 1.0));
    const double twilight = elevation < 0.0 ? std::exp(elevation / k_twilight_scale_rad) : 1.0;
    p.scale = k_radiance_per_kcd * twilight * std::max(double(sky_intensity), 0.0);
    return p;
}

// Sky radiance for a direction in the upper hemisphere (y > 0).
glm::dvec3 sky_radiance(const prepared_sky& p, glm::dvec3 dir) {
    const double cos_theta = std::max(dir.y, k_min_cos_view);
    const double gamma = std::acos(std::clamp(glm::dot(dir, p.sun), -1.0, 1.0));
    const double luminance = p.zenith_y_over_f0 * perez(p.py, cos_theta, gamma);
    const double x = p.zenith_x_over_f0 * perez(p.px, cos_theta, gamma);
    const double y = p.zenith_yc_over_f0 * perez(p.pyc, cos_theta, gamma);
    const glm::dvec3 rgb = xyy_to_linear_srgb(x, y, luminance) * p.scale;
    return glm::max(rgb, glm::dvec3(k_min_channel_fraction * luminance * p.scale));
}

// Irradiance on a horizontal plane from the sky alone, for sky_intensity = 1: midpoint rule
// over the upper hemisphere of L cos(theta) dw. The sun is put at azimuth 0 so the result is a
// pure function of (sun elevation, turbidity) whatever the azimuth; it does not depend on it.
glm::dvec3 horizontal_sky_irradiance(float sun_y, float turbidity) {
    const float horizontal = std::sqrt(std::max(0.0f, 1.0f - sun_y * sun_y));
    const prepared_sky p = prepare(glm::vec3(0.0f, sun_y, -horizontal), turbidity, 1.0f);
    const double d_theta = 0.5 * k_pi / k_ground_samples_theta;
    const double d_phi = 2.0 * k_pi / k_ground_samples_phi;
    glm::dvec3 sum(0.0);
    for (int j = 0; j < k_ground_samples_theta; ++j) {
        const double theta = (j + 0.5) * d_theta;
        const double weight = std::cos(theta) * std::sin(theta) * d_theta * d_phi;
        for (int i = 0; i < k_ground_samples_phi; ++i) {
            const double phi = (i + 0.5) * d_phi;
            const glm::dvec3 dir(std::sin(theta) * std::sin(phi), std::cos(theta),
                                 -std::sin(theta) * std::cos(phi));
            sum += weight * sky_radiance(p, dir);
        }
    }
    return sum;
}

}  // namespace

glm::vec3 ground_radiance(const sky_model& sky) {
    const glm::vec3 sun(unit_sun(sky.sun_direction));
    const auto turbidity = float(usable_turbidity(sky.turbidity));
    // The integral costs ~2k sky evaluations; the renderer and the SH projection ask for it once
    // per ground direction, so remember the last answer (per thread: no sharing, no locks).
    struct memo {
        bool valid = false;
        float sun_y = 0.0f;
        float turbidity = 0.0f;
        glm::dvec3 irradiance{0.0};
    };
    thread_local memo last;
    if (!last.valid || last.sun_y != sun.y || last.turbidity != turbidity) {
        last = {true, sun.y, turbidity, horizontal_sky_irradiance(sun.y, turbidity)};
    }
    const glm::dvec3 e = last.irradiance * std::max(double(sky.sky_intensity), 0.0) +
                         glm::dvec3(sky.sun_irradiance) * std::max(0.0, double(sun.y));
    // Lambertian ground: radiance = albedo * E / pi.
    return glm::vec3(glm::dvec3(sky.ground_albedo) * e / k_pi);
}

glm::vec3 sky_model::radiance(glm::vec3 unit_dir) const {
    if (unit_dir.y <= 0.0f) return ground_radiance(*this);
    const prepared_sky p = prepare(sun_direction, turbidity, sky_intensity);
    return glm::vec3(sky_radiance(p, glm::normalize(glm::dvec3(unit_dir))));
}

sh9_rgb project_sky(const sky_model& sky, int samples_theta, int samples_phi) {
    const prepared_sky p = prepare(sky.sun_direction, sky.turbidity, sky.sky_intensity);
    const glm::vec3 ground = ground_radiance(sky);
    return project_radiance(
        [&](glm::vec3 dir) {
            if (dir.y <= 0.0f) return ground;
            return glm::vec3(sky_radiance(p, glm::normalize(glm::dvec3(dir))));
        },
        samples_theta, samples_phi);
}

glm::vec3 sun_direction_from_angles(float elevation_deg, float azimuth_deg) {
    const double e = glm::radians(double(elevation_deg));
    const double a = glm::radians(double(azimuth_deg));
    // Azimuth clockwise from north (-z) towards east (+x), seen from above.
    return glm::vec3(float(std::cos(e) * std::sin(a)), float(std::sin(e)),
                     float(-std::cos(e) * std::cos(a)));
}

glm::mat3 azimuth_rotation(float delta_azimuth_deg) {
    // (sin a, y, -cos a) -> (sin(a + d), y, -cos(a + d)) by the angle-sum identities:
    // x' = cos d x - sin d z, z' = sin d x + cos d z. glm matrices are built from columns.
    const double d = glm::radians(double(delta_azimuth_deg));
    const auto c = float(std::cos(d));
    const auto s = float(std::sin(d));
    return glm::mat3(glm::vec3(c, 0.0f, s), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(-s, 0.0f, c));
}

namespace {

// Representative wavelengths (micrometres) for the linear sRGB channels; sampling the
// transmittance at one wavelength per channel is the approximation here.
constexpr double k_channel_wavelength_um[3] = {0.680, 0.550, 0.440};
constexpr double k_sun_angular_radius_rad = 0.267 * k_pi / 180.0;

// Relative optical air mass for sun zenith angle theta_s (Kasten 1966, as quoted in Preetham
// 1999, Appendix A.2): m = 1 / (cos theta + 0.15 (93.885 - theta_deg)^-1.253). Finite up to
// theta = 90 degrees (m ~ 37 on the horizon).
double relative_air_mass(double theta_s) {
    const double theta_deg = theta_s * 180.0 / k_pi;
    return 1.0 / (std::cos(theta_s) + 0.15 * std::pow(93.885 - theta_deg, -1.253));
}

// Direct-beam transmittance per channel, Preetham 1999, Appendix A.2 (after Iqbal 1983):
// Rayleigh tau_R = exp(-0.008735 lambda^-4.08 m) and Angstrom aerosol tau_a =
// exp(-beta lambda^-alpha m) with alpha = 1.3, beta = 0.04608365 T - 0.04586025. Ozone, water
// vapour and mixed-gas absorption are left out (small in the visible at these wavelengths).
glm::dvec3 sun_transmittance(double theta_s, double turbidity) {
    const double m = relative_air_mass(theta_s);
    const double beta = 0.04608365 * turbidity - 0.04586025;
    glm::dvec3 out;
    for (int c = 0; c < 3; ++c) {
        const double lambda = k_channel_wavelength_um[c];
        const double rayleigh = 0.008735 * std::pow(lambda, -4.08);
        const double aerosol = beta * std::pow(lambda, -1.3);
        out[c] = std::exp(-(rayleigh + aerosol) * m);
    }
    return out;
}

double rec709_luminance(glm::dvec3 rgb) {
    return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z;
}

}  // namespace

glm::vec3 sun_radiance_color(float elevation_rad, float turbidity) {
    if (std::isnan(elevation_rad)) return glm::vec3(0.0f);  // no sun direction: no direct light
    const double t = usable_turbidity(turbidity);
    const double elevation = std::clamp(double(elevation_rad), -0.5 * k_pi, 0.5 * k_pi);
    // The disk sets over its own angular diameter; below that no direct light is left.
    const double r = k_sun_angular_radius_rad;
    const double u = std::clamp((elevation + r) / (2.0 * r), 0.0, 1.0);
    const double visible = u * u * (3.0 - 2.0 * u);
    if (visible <= 0.0) return glm::vec3(0.0f);
    const double theta_s = 0.5 * k_pi - std::max(elevation, 0.0);
    const double clear_noon = rec709_luminance(sun_transmittance(0.0, k_min_turbidity));
    return glm::vec3(sun_transmittance(theta_s, t) * (visible / clear_noon));
}

}  // namespace sylva
