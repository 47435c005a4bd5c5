// LDR-FLIP: Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom, Fairchild, "FLIP: A Difference
// Evaluator for Alternating Images", Proc. ACM Comput. Graph. Interact. Tech. 3(2), 2020
// (HPG 2020), doi:10.1145/3406183. Structure and constants follow the paper's Section 4 (colour
// pipeline and feature pipeline, combined into the final error map) and the authors' published
// reference code (flip.py / FLIP.cpp); we cite sections and constants rather than equation
// numbers, which we could not check against the paper while writing this.
//
// Per pixel, with `a` the reference and `b` the test, both sRGB-encoded:
//   Colour pipeline
//     1. sRGB -> linear RGB -> XYZ -> YCxCz (opponent space; Y' = 116 Y/Yn - 16,
//        Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn), white = linear RGB (1,1,1)).
//     2. Each channel is filtered with its contrast sensitivity function, a sum of Gaussians in
//        the spatial domain: g(x) = a1 sqrt(pi/b1) exp(-pi^2 x^2/b1) + a2 sqrt(pi/b2) exp(-pi^2
//        x^2/b2), x in degrees of visual angle, with (a1, b1, a2, b2) =
//          achromatic  (1, 0.0047, 0, 1e-5), red-green (1, 0.0053, 0, 1e-5),
//          blue-yellow (34.1, 0.04, 13.5, 0.025),
//        sampled on a (2r+1)^2 grid, r = ceil(3 sqrt(max b / (2 pi^2)) ppd), and normalised to
//        sum 1 per channel.
//     3. Back to linear RGB, clamped to [0, 1] (the gamut box), then CIELAB, then the Hunt
//        adjustment a* *= L*/100, b* *= L*/100.
//     4. HyAB distance |dL| + sqrt(da^2 + db^2) (Abasi, Tehran, Fairchild 2020), raised to
//        qc = 0.7, and redistributed into [0, 1] with cmax = HyAB(green, blue)^qc of the
//        Hunt-adjusted primaries, pc = 0.4, pt = 0.95: below pc cmax it maps linearly to
//        [0, pt), above it linearly from pt to 1 at cmax.
//   Feature pipeline, on the unfiltered luminance Y/Yn in [0, 1]
//     5. Edges: first derivative of a Gaussian; points: second derivative; sd = 0.5 w ppd with
//        w = 0.082 degrees, radius ceil(3 sd), positive weights normalised to sum 1 and negative
//        to -1; applied along x and along y, each detector's response being the length of the
//        (x, y) response vector.
//     6. dE_f = (max(|edge_a - edge_b|, |point_a - point_b|) / sqrt(2))^qf with qf = 0.5.
//   Combined
//     7. dE = dE_c^(1 - dE_f), pooled by the mean over all pixels.
// Borders are mirrored including the edge pixel (d c b a | a b c d ...), as scipy's "symm"
// boundary in the reference code. Kernels are applied as separable correlations in double
// precision (every kernel above is a sum of products of 1D kernels; convolution and correlation
// differ only in the sign of the antisymmetric edge kernel, whose response enters as a length).
//
// (The authors' later python/flip_api.py replicates the edge pixel instead, a a a | a b c; the
// two differ only within a filter radius of the border.)
//
// What this leaves out compared with the reference tools: HDR-FLIP (exposure bracketing), error
// map output, histograms and percentile pooling; only the mean is returned (the per-pixel map is
// flip_detail::error_map, for tests). Alpha is ignored. The numbers have been checked by
// hand-computed cases (tests/measure/image_metrics_test.cpp for constant images,
// tests/measure/flip_detail_test.cpp for each spatial step on a step edge, a single bright
// pixel and sinusoids), not yet against the authors' tool itself.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "measure/flip_detail.h"
#include "measure/image_checks.h"
#include "measure/image_metrics.h"

namespace sylva {

namespace flip_detail {
namespace {

using vec3 = std::array<double, 3>;
using mat3 = std::array<vec3, 3>;

constexpr double k_qc = 0.7;
constexpr double k_qf = 0.5;
constexpr double k_pc = 0.4;
constexpr double k_pt = 0.95;
constexpr double k_feature_width_degrees = 0.082;

// Linear sRGB (Rec. 709 primaries, D65) to XYZ, the exact rationals of the reference code.
constexpr mat3 k_rgb_to_xyz = {{{10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0},
                                {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0},
                                {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0}}};

vec3 multiply(const mat3& m, const vec3& v) {
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

mat3 inverse(const mat3& m) {
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    mat3 r{};
    r[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / det;
    r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
    r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
    r[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / det;
    r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
    r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
    r[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / det;
    r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
    r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
    return r;
}

const mat3& xyz_to_rgb() {
    static const mat3 m = inverse(k_rgb_to_xyz);
    return m;
}

// The white point: XYZ of linear RGB (1, 1, 1).
const vec3& white() {
    static const vec3 w = multiply(k_rgb_to_xyz, {1.0, 1.0, 1.0});
    return w;
}

double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

vec3 xyz_to_ycxcz(const vec3& xyz) {
    const vec3& n = white();
    const double x = xyz[0] / n[0], y = xyz[1] / n[1], z = xyz[2] / n[2];
    return {116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)};
}

vec3 ycxcz_to_xyz(const vec3& o) {
    const vec3& n = white();
    const double y = (o[0] + 16.0) / 116.0;
    return {(y + o[1] / 500.0) * n[0], y * n[1], (y - o[2] / 200.0) * n[2]};
}

// Linear RGB to CIELAB (relative to the same white), then the Hunt adjustment.
vec3 linear_rgb_to_hunt_lab(const vec3& rgb) {
    const vec3 xyz = multiply(k_rgb_to_xyz, rgb);
    const vec3& n = white();
    constexpr double delta = 6.0 / 29.0;
    const auto f = [](double t) {
        return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
    };
    const double fx = f(xyz[0] / n[0]), fy = f(xyz[1] / n[1]), fz = f(xyz[2] / n[2]);
    const double l = 116.0 * fy - 16.0;
    return {l, 0.01 * l * 500.0 * (fx - fy), 0.01 * l * 200.0 * (fy - fz)};
}

double hyab(const vec3& p, const vec3& q) {
    return std::abs(p[0] - q[0]) + std::hypot(p[1] - q[1], p[2] - q[2]);
}

// Mirror an index into [0, n): ... 1 0 | 0 1 ... n-1 | n-1 n-2 ..., for any distance outside.
std::size_t mirror(std::ptrdiff_t i, std::ptrdiff_t n) {
    const std::ptrdiff_t period = 2 * n;
    std::ptrdiff_t m = i % period;
    if (m < 0) m += period;
    return std::size_t(m < n ? m : period - 1 - m);
}

// out(x, y) = sum_{i,j} kx[i] ky[j] in(x + i - r, y + j - r), kernels of odd length 2r + 1.
plane correlate(const plane& in, const std::vector<double>& kx, const std::vector<double>& ky) {
    const auto w = std::ptrdiff_t(in.width);
    const auto h = std::ptrdiff_t(in.height);
    const auto rx = std::ptrdiff_t(kx.size() / 2);
    const auto ry = std::ptrdiff_t(ky.size() / 2);
    plane rows{in.width, in.height, std::vector<double>(in.v.size())};
    for (std::ptrdiff_t y = 0; y < h; ++y)
        for (std::ptrdiff_t x = 0; x < w; ++x) {
            double s = 0.0;
            for (std::ptrdiff_t i = -rx; i <= rx; ++i)
                s += kx[std::size_t(i + rx)] * in.v[std::size_t(y * w) + mirror(x + i, w)];
            rows.v[std::size_t(y * w + x)] = s;
        }
    plane out{in.width, in.height, std::vector<double>(in.v.size())};
    for (std::ptrdiff_t y = 0; y < h; ++y)
        for (std::ptrdiff_t x = 0; x < w; ++x) {
            double s = 0.0;
            for (std::ptrdiff_t j = -ry; j <= ry; ++j)
                s += ky[std::size_t(j + ry)] * rows.v[mirror(y + j, h) * in.width + std::size_t(x)];
            out.v[std::size_t(y * w + x)] = s;
        }
    return out;
}

// The largest b of the three CSFs sets one filter radius for all, as in the reference code.
constexpr double k_csf_max_b = 0.04;

}  // namespace

// Filters with the CSF sampled on the (2r+1)^2 grid and normalised to sum 1. Each Gaussian term
// is separable, a * sqrt(pi/b) * k(x) k(y) with k(x) = exp(-pi^2 (x/ppd)^2 / b), so the 2D
// filter is a weighted sum of separable passes with 1D kernels k / sum(k).
plane filter_csf(const plane& in, const csf& f, double ppd) {
    const double pi = std::numbers::pi;
    const auto r = std::ptrdiff_t(std::ceil(3.0 * std::sqrt(k_csf_max_b / (2.0 * pi * pi)) * ppd));
    struct term {
        double weight;
        std::vector<double> kernel;
    };
    std::vector<term> terms;
    double total = 0.0;
    for (const auto& [a, b] : {std::array<double, 2>{f.a1, f.b1}, std::array<double, 2>{f.a2, f.b2}}) {
        if (a == 0.0) continue;
        std::vector<double> k(std::size_t(2 * r + 1));
        double sum = 0.0;
        for (std::ptrdiff_t i = -r; i <= r; ++i) {
            const double x = double(i) / ppd;
            k[std::size_t(i + r)] = std::exp(-pi * pi * x * x / b);
            sum += k[std::size_t(i + r)];
        }
        for (double& v : k) v /= sum;
        const double weight = a * std::sqrt(pi / b) * sum * sum;  // this term's share of the grid sum
        terms.push_back({weight, std::move(k)});
        total += weight;
    }
    plane out{in.width, in.height, std::vector<double>(in.v.size(), 0.0)};
    for (const term& t : terms) {
        const plane part = correlate(in, t.kernel, t.kernel);
        for (std::size_t i = 0; i < out.v.size(); ++i) out.v[i] += t.weight / total * part.v[i];
    }
    return out;
}

namespace {

// Hunt-adjusted CIELAB of the CSF-filtered image (steps 1-3), and its normalised luminance Y/Yn.
struct prepared {
    std::vector<vec3> lab;
    plane luminance;
};

prepared prepare(const image_rgba8& image, double ppd) {
    const std::size_t count = std::size_t(image.width) * image.height;
    std::array<plane, 3> opponent;
    for (plane& p : opponent) p = plane{image.width, image.height, std::vector<double>(count)};
    prepared out;
    out.luminance = plane{image.width, image.height, std::vector<double>(count)};
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint8_t* t = &image.texels[i * 4];
        const vec3 rgb{srgb_to_linear(t[0] / 255.0), srgb_to_linear(t[1] / 255.0), srgb_to_linear(t[2] / 255.0)};
        const vec3 o = xyz_to_ycxcz(multiply(k_rgb_to_xyz, rgb));
        for (std::size_t c = 0; c < 3; ++c) opponent[c].v[i] = o[c];
        out.luminance.v[i] = (o[0] + 16.0) / 116.0;
    }
    const plane y = filter_csf(opponent[0], k_csf_achromatic, ppd);
    const plane cx = filter_csf(opponent[1], k_csf_red_green, ppd);
    const plane cz = filter_csf(opponent[2], k_csf_blue_yellow, ppd);
    out.lab.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        vec3 rgb = multiply(xyz_to_rgb(), ycxcz_to_xyz({y.v[i], cx.v[i], cz.v[i]}));
        for (double& c : rgb) c = std::clamp(c, 0.0, 1.0);
        out.lab[i] = linear_rgb_to_hunt_lab(rgb);
    }
    return out;
}

}  // namespace

// The 1D kernels of a feature detector (step 5): `across` is the derivative direction (first
// derivative of a Gaussian for edges, second for points), positive and negative weights
// normalised to 1 and -1; `along` is the Gaussian normalised to sum 1. Their outer product is
// the reference code's 2D kernel.
feature_kernels make_feature_kernels(double ppd, bool points) {
    const double sd = 0.5 * k_feature_width_degrees * ppd;
    const auto r = std::ptrdiff_t(std::ceil(3.0 * sd));
    feature_kernels k{std::vector<double>(std::size_t(2 * r + 1)), std::vector<double>(std::size_t(2 * r + 1))};
    double positive = 0.0, negative = 0.0, along_sum = 0.0;
    for (std::ptrdiff_t i = -r; i <= r; ++i) {
        const double x = double(i);
        const double g = std::exp(-x * x / (2.0 * sd * sd));
        const double d = points ? (x * x / (sd * sd) - 1.0) * g : -x * g;
        k.across[std::size_t(i + r)] = d;
        k.along[std::size_t(i + r)] = g;
        if (d > 0.0) positive += d;
        if (d < 0.0) negative -= d;
        along_sum += g;
    }
    for (double& d : k.across) {
        if (d > 0.0 && positive > 0.0) d /= positive;
        if (d < 0.0 && negative > 0.0) d /= negative;
    }
    for (double& g : k.along) g /= along_sum;
    return k;
}

// Length of the (x, y) response of a feature detector at every pixel.
std::vector<double> feature_strength(const plane& luminance, const feature_kernels& k) {
    const plane fx = correlate(luminance, k.across, k.along);
    const plane fy = correlate(luminance, k.along, k.across);
    std::vector<double> out(fx.v.size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = std::hypot(fx.v[i], fy.v[i]);
    return out;
}

std::vector<double> error_map(const image_rgba8& a, const image_rgba8& b, double pixels_per_degree) {
    require_same_size(a, b, "flip_error");
    if (!(pixels_per_degree > 0.0) || !std::isfinite(pixels_per_degree))
        throw std::invalid_argument("flip_error: pixels_per_degree must be positive and finite");
    const std::size_t count = std::size_t(a.width) * a.height;
    if (count == 0) return {};

    const prepared ref = prepare(a, pixels_per_degree);
    const prepared test = prepare(b, pixels_per_degree);

    const double cmax = std::pow(hyab(linear_rgb_to_hunt_lab({0.0, 1.0, 0.0}), linear_rgb_to_hunt_lab({0.0, 0.0, 1.0})), k_qc);
    const double pccmax = k_pc * cmax;

    const feature_kernels edges = make_feature_kernels(pixels_per_degree, false);
    const feature_kernels points = make_feature_kernels(pixels_per_degree, true);
    const std::vector<double> edge_a = feature_strength(ref.luminance, edges);
    const std::vector<double> edge_b = feature_strength(test.luminance, edges);
    const std::vector<double> point_a = feature_strength(ref.luminance, points);
    const std::vector<double> point_b = feature_strength(test.luminance, points);

    std::vector<double> map(count);
    for (std::size_t i = 0; i < count; ++i) {
        // Step 4: colour difference, compressed and redistributed into [0, 1].
        const double p = std::pow(hyab(ref.lab[i], test.lab[i]), k_qc);
        const double color = p < pccmax ? (k_pt / pccmax) * p : k_pt + (p - pccmax) / (cmax - pccmax) * (1.0 - k_pt);
        // Step 6: feature difference.
        const double feature_delta = std::max(std::abs(edge_a[i] - edge_b[i]), std::abs(point_a[i] - point_b[i]));
        const double feature = std::pow(feature_delta / std::numbers::sqrt2, k_qf);
        // Step 7.
        map[i] = std::pow(color, 1.0 - feature);
    }
    return map;
}

}  // namespace flip_detail

double flip_error(const image_rgba8& a, const image_rgba8& b, double pixels_per_degree) {
    const std::vector<double> map = flip_detail::error_map(a, b, pixels_per_degree);
    if (map.empty()) return 0.0;
    double sum = 0.0;
    for (const double error : map) sum += error;
    return sum / double(map.size());
}

}  // namespace sylva
