#include "lighting/environment_map.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <numbers>
#include <stdexcept>
#include <string>

#include "io/input_file.h"

namespace sylva {

namespace {

constexpr double k_pi = std::numbers::pi;

[[noreturn]] void fail(const std::string& file, const std::string& problem) {
    throw std::runtime_error("environment map " + file + ": " + problem);
}

bool is_float_data(OIIO::TypeDesc format) {
    return format.basetype == OIIO::TypeDesc::FLOAT || format.basetype == OIIO::TypeDesc::HALF ||
           format.basetype == OIIO::TypeDesc::DOUBLE;
}

// Radiance is finite and non-negative: anything else carries no usable energy.
bool sanitise_texel(float* rgb) {
    bool bad = false;
    for (int c = 0; c < 3; ++c) bad = bad || !std::isfinite(rgb[c]) || rgb[c] < 0.0f;
    if (bad) rgb[0] = rgb[1] = rgb[2] = 0.0f;
    return bad;
}

// Exact solid angle of one texel of row `row`: the band between polar angles theta0 and theta1
// covers 2 pi (cos theta0 - cos theta1), split over `width` columns.
double texel_solid_angle(int row, int width, int height) {
    const double theta0 = k_pi * row / height;
    const double theta1 = k_pi * (row + 1) / height;
    return (std::cos(theta0) - std::cos(theta1)) * (2.0 * k_pi / width);
}

// The map is constant over each texel, so its projection is a sum of L times the exact
// integral of each basis function over the texel, theta in [theta0, theta1] and phi in
// [phi0, phi1]. With x = sin t sin p, y = cos t, z = -sin t cos p and dw = sin t dt dp, each
// basis function splits into products of these one-dimensional integrals.
struct theta_moments {
    double s1;    // integral of sin t dt = cos t0 - cos t1 (times dp: the solid angle)
    double s1c1;  // sin t cos t  = (u0^2 - u1^2) / 2, u = cos t
    double s1c2;  // sin t cos^2 t = (u0^3 - u1^3) / 3
    double s2;    // sin^2 t      = [t / 2 - sin 2t / 4]
    double s2c1;  // sin^2 t cos t = [sin^3 t / 3]
    double s3;    // sin^3 t      = (u0 - u1) - (u0^3 - u1^3) / 3
};
struct phi_moments {
    double one;  // p1 - p0
    double s;    // integral of sin p dp = cos p0 - cos p1
    double c;    // cos p            = sin p1 - sin p0
    double ss;   // sin^2 p          = [p / 2 - sin 2p / 4]
    double cc;   // cos^2 p          = [p / 2 + sin 2p / 4]
    double sc;   // sin p cos p      = [sin^2 p / 2]
};

std::vector<theta_moments> row_moments(int height) {
    std::vector<theta_moments> out;
    for (int j = 0; j < height; ++j) {
        const double t0 = k_pi * j / height;
        const double t1 = k_pi * (j + 1) / height;
        const double u0 = std::cos(t0);
        const double u1 = std::cos(t1);
        const auto sin3 = [](double t) { return std::pow(std::sin(t), 3.0); };
        out.push_back({u0 - u1, (u0 * u0 - u1 * u1) / 2.0, (u0 * u0 * u0 - u1 * u1 * u1) / 3.0,
                       (t1 - t0) / 2.0 - (std::sin(2.0 * t1) - std::sin(2.0 * t0)) / 4.0,
                       (sin3(t1) - sin3(t0)) / 3.0,
                       (u0 - u1) - (u0 * u0 * u0 - u1 * u1 * u1) / 3.0});
    }
    return out;
}

std::vector<phi_moments> column_moments(int width) {
    std::vector<phi_moments> out;
    for (int i = 0; i < width; ++i) {
        // Azimuth from north: u = i / width is phi = (u - 0.5) 2 pi (orientation in the header).
        const double p0 = 2.0 * k_pi * (double(i) / width - 0.5);
        const double p1 = 2.0 * k_pi * (double(i + 1) / width - 0.5);
        const double s0 = std::sin(p0);
        const double s1 = std::sin(p1);
        out.push_back({p1 - p0, std::cos(p0) - std::cos(p1), s1 - s0,
                       (p1 - p0) / 2.0 - (std::sin(2.0 * p1) - std::sin(2.0 * p0)) / 4.0,
                       (p1 - p0) / 2.0 + (std::sin(2.0 * p1) - std::sin(2.0 * p0)) / 4.0,
                       (s1 * s1 - s0 * s0) / 2.0});
    }
    return out;
}

// Sloan's table (spherical_harmonics.h) with exact constants, integrated over one texel.
std::array<double, 9> texel_basis_integrals(const theta_moments& t, const phi_moments& p) {
    const double y0 = 0.5 / std::sqrt(k_pi);
    const double y1 = std::sqrt(3.0 / (4.0 * k_pi));
    const double y2_mixed = std::sqrt(15.0 / (4.0 * k_pi));
    const double y2_zonal = std::sqrt(5.0 / (16.0 * k_pi));
    const double y2_sectoral = std::sqrt(15.0 / (16.0 * k_pi));
    return {y0 * t.s1 * p.one,
            y1 * t.s1c1 * p.one,                            // y
            -y1 * t.s2 * p.c,                               // z
            y1 * t.s2 * p.s,                                // x
            y2_mixed * t.s2c1 * p.s,                        // x y
            -y2_mixed * t.s2c1 * p.c,                       // y z
            y2_zonal * (3.0 * t.s3 * p.cc - t.s1 * p.one),  // 3 z^2 - 1
            -y2_mixed * t.s3 * p.sc,                        // x z
            y2_sectoral * (t.s3 * p.ss - t.s1c2 * p.one)};  // x^2 - y^2
}

}  // namespace

glm::vec3 environment_map_direction(int column, int row, int width, int height) {
    const double theta = k_pi * (row + 0.5) / height;
    const double phi = 2.0 * k_pi * ((column + 0.5) / width - 0.5);
    const double s = std::sin(theta);
    return glm::vec3(float(s * std::sin(phi)), float(std::cos(theta)), float(-s * std::cos(phi)));
}

environment_map load_environment_map(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) fail(name, "no such file");
    check_input_file(path, k_max_image_bytes);  // a directory or device is refused here
    auto in = OIIO::ImageInput::open(name);
    if (!in) fail(name, "cannot read it: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    check_image_dimensions("environment map " + name, spec.width, spec.height);
    if (!is_float_data(spec.format))
        fail(name, "holds " + std::string(spec.format.c_str()) +
                       " data; expected HDR float radiance (.hdr or .exr)");
    if (spec.nchannels < 3)
        fail(name, "has " + std::to_string(spec.nchannels) + " channel(s); expected RGB");
    if (spec.height < 1 || spec.width != 2 * spec.height)
        fail(name, "is " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                       " pixels; a latitude-longitude map is twice as wide as it is high");
    environment_map map;
    map.width = spec.width;
    map.height = spec.height;
    map.rgb.resize(std::size_t(map.width) * std::size_t(map.height) * 3);
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, map.rgb.data()))
        fail(name, "cannot read its pixels: " + in->geterror());
    in->close();
    for (std::size_t i = 0; i < map.rgb.size(); i += 3)
        if (sanitise_texel(&map.rgb[i])) ++map.sanitised_texels;
    return map;
}

sh9_rgb project_environment_map(const environment_map& map) {
    const std::vector<theta_moments> rows = row_moments(map.height);
    const std::vector<phi_moments> columns = column_moments(map.width);
    std::array<glm::dvec3, 9> sum{};
    for (int j = 0; j < map.height; ++j) {
        for (int i = 0; i < map.width; ++i) {
            const float* texel =
                &map.rgb[(std::size_t(j) * std::size_t(map.width) + std::size_t(i)) * 3];
            const glm::dvec3 l(texel[0], texel[1], texel[2]);
            const std::array<double, 9> y =
                texel_basis_integrals(rows[std::size_t(j)], columns[std::size_t(i)]);
            for (std::size_t k = 0; k < 9; ++k) sum[k] += l * y[k];
        }
    }
    // Texels are finite and below FLT_MAX and |integral of Y_k over a texel| <= its solid angle
    // times 1.1: |c| < 14 FLT_MAX at worst; hold the result at the largest float as projections do.
    constexpr double k_max = 3.4028234663852886e38;
    sh9_rgb out;
    for (std::size_t k = 0; k < 9; ++k)
        for (int c = 0; c < 3; ++c) out.c[k][c] = float(std::clamp(sum[k][c], -k_max, k_max));
    return out;
}

environment_map downsample_environment_map(const environment_map& map, int width, int height) {
    environment_map out;
    out.width = width;
    out.height = height;
    out.rgb.assign(std::size_t(width) * std::size_t(height) * 3, 0.0f);
    if (map.width < 1 || map.height < 1) return out;
    std::vector<glm::dvec4> sum(std::size_t(width) * std::size_t(height), glm::dvec4(0.0));
    for (int j = 0; j < map.height; ++j) {
        const double weight = texel_solid_angle(j, map.width, map.height);
        const auto row = std::size_t(std::int64_t(j) * height / map.height);
        for (int i = 0; i < map.width; ++i) {
            const auto column = std::size_t(std::int64_t(i) * width / map.width);
            const float* texel =
                &map.rgb[(std::size_t(j) * std::size_t(map.width) + std::size_t(i)) * 3];
            sum[row * std::size_t(width) + column] +=
                glm::dvec4(glm::dvec3(texel[0], texel[1], texel[2]) * weight, weight);
        }
    }
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            const glm::dvec4& s = sum[std::size_t(j) * std::size_t(width) + std::size_t(i)];
            float* target = &out.rgb[(std::size_t(j) * std::size_t(width) + std::size_t(i)) * 3];
            if (s.w > 0.0) {
                for (int c = 0; c < 3; ++c) target[c] = float(s[c] / s.w);
            } else {  // no source centre inside: the nearest source texel
                const int si = std::min(map.width - 1, int((i + 0.5) * map.width / width));
                const int sj = std::min(map.height - 1, int((j + 0.5) * map.height / height));
                const float* texel =
                    &map.rgb[(std::size_t(sj) * std::size_t(map.width) + std::size_t(si)) * 3];
                std::copy(texel, texel + 3, target);
            }
        }
    }
    return out;
}

}  // namespace sylva
