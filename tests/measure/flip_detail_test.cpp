// FLIP's spatial steps (Andersson et al. 2020; measure/flip_detail.h) on non-constant images,
// against values derived by hand. Constant images (image_metrics_test.cpp) pass through the CSF
// filters unchanged and give the feature detectors nothing to see, so only these tests check the
// filters, the detectors and how their outputs combine.
//
// The detector tests use ppd = 20: sd = 0.5 * 0.082 * 20 = 0.82 pixels, radius ceil(3 sd) = 3,
// 2 sd^2 = 1.3448, and the Gaussian's samples
//   g(0) = 1, g(1) = exp(-1/1.3448) = exp(-0.743605) = 0.475397,
//   g(2) = exp(-4/1.3448) = exp(-2.974420) = 0.051077, g(3) = exp(-9/1.3448) = 0.0012402,
// so `along` = g / (1 + 2 (0.475397 + 0.051077 + 0.0012402)) = g / 2.055429:
//   along(0) = 0.486517, along(1) = 0.231289.
#include "measure/flip_detail.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "measure/image_metrics.h"

namespace sylva {
namespace {

using flip_detail::plane;

constexpr double k_detector_ppd = 20.0;

plane make_plane(std::size_t width, std::size_t height, double value = 0.0) {
    return plane{width, height, std::vector<double>(width * height, value)};
}

image_rgba8 black_image(std::uint32_t width, std::uint32_t height) {
    image_rgba8 image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4, 0)};
    for (std::size_t i = 0; i < std::size_t(width) * height; ++i) image.texels[i * 4 + 3] = 255;
    return image;
}

void paint_white(image_rgba8& image, std::uint32_t x, std::uint32_t y) {
    for (std::size_t c = 0; c < 3; ++c) image.at(x, y)[c] = 255;
}

// A unit step along x (0 left of column `step`, 1 from it on), the same on every row.
plane step_edge(std::size_t width, std::size_t height, std::size_t step) {
    plane p = make_plane(width, height);
    for (std::size_t y = 0; y < height; ++y)
        for (std::size_t x = step; x < width; ++x) p.v[y * width + x] = 1.0;
    return p;
}

TEST(flip_detail, edge_detector_on_a_unit_step_is_one_beside_it_and_one_plus_k1_further) {
    // The edge kernel across the step is d(i) = -i g(i), normalised so that its positive weights
    // (i < 0) sum to 1 and its negative ones (i > 0) to -1. Its positive sum is
    // P = g(1) + 2 g(2) + 3 g(3) = 0.475397 + 0.102154 + 0.003721 = 0.581272, so
    // k[1] = -0.475397 / 0.581272 = -0.817857, k[2] = -0.175742, k[3] = -0.006401.
    // Correlating the step (the `along` pass leaves a column-constant image unchanged):
    //   at x = 7 (last 0):  k[1] + k[2] + k[3] = -1, whatever the Gaussian: the normalisation;
    //   at x = 8 (first 1): k[0] + k[1] + k[2] + k[3] = 0 - 1 = -1;
    //   at x = 6 or 9:      |k[2] + k[3]| = |k[-1] + k[0..3]| = 1 + k[1] = 0.182143;
    //   at x = 5 or 10:     |k[3]| = 0.006401; beyond the radius 0 (the kernel sums to 0).
    // The y response is 0 (the across kernel sums to 0 down a constant column).
    const plane edge = step_edge(16, 5, 8);
    const auto kernels = flip_detail::make_feature_kernels(k_detector_ppd, false);
    ASSERT_EQ(kernels.across.size(), 7u);
    const std::vector<double> strength = flip_detail::feature_strength(edge, kernels);
    const double expected[16] = {0, 0,        0,        0, 0, 0.006401, 0.182143, 1,
                                 1, 0.182143, 0.006401, 0, 0, 0,        0,        0};
    for (std::size_t y = 0; y < 5; ++y)
        for (std::size_t x = 0; x < 16; ++x)
            EXPECT_NEAR(strength[y * 16 + x], expected[x], x == 7 || x == 8 ? 1e-12 : 1e-6)
                << "x " << x << " y " << y;
}

TEST(flip_detail, point_detector_on_a_single_bright_pixel) {
    // The point kernel across is p(i) = (i^2/sd^2 - 1) g(i), sd^2 = 0.6724: p(0) = -1 is its only
    // negative weight (|i| >= 1 > sd elsewhere), so it normalises to exactly -1; the positive
    // sum is P = 2 (0.487210 * 0.475397 + 4.948840 * 0.051077 + 12.384890 * 0.0012402)
    // = 2 (0.231618 + 0.252772 + 0.015360) = 0.999501.
    // At the bright pixel both the x and the y response are across(0) along(0) = -0.486517, so
    // the strength is sqrt(2) * 0.486517 = 0.688038. One pixel to the right the x response is
    // across(-1) along(0) = (0.231618 / 0.999501) * 0.486517 = 0.112742 and the y response
    // along(-1) across(0) = -0.231289: strength hypot(0.112742, 0.231289) = 0.257304.
    // The edge detector sees nothing at the pixel itself (its across(0) is 0) and
    // k[1] along(0) = 0.817857 * 0.486517 = 0.397901 one pixel beside it.
    plane dot = make_plane(15, 15);
    dot.v[7 * 15 + 7] = 1.0;
    const std::vector<double> points =
        flip_detail::feature_strength(dot, flip_detail::make_feature_kernels(k_detector_ppd, true));
    const std::vector<double> edges = flip_detail::feature_strength(
        dot, flip_detail::make_feature_kernels(k_detector_ppd, false));
    EXPECT_NEAR(points[7 * 15 + 7], 0.688038, 1e-6);
    EXPECT_NEAR(points[7 * 15 + 8], 0.257304, 1e-6);
    EXPECT_NEAR(points[8 * 15 + 7], 0.257304, 1e-6);  // the same below: the detector is symmetric
    EXPECT_EQ(edges[7 * 15 + 7], 0.0);
    EXPECT_NEAR(edges[7 * 15 + 8], 0.397901, 1e-6);
    EXPECT_NEAR(points[7 * 15 + 11], 0.0, 1e-15);  // 4 pixels away: beyond the radius
}

// The gain of `f` for a sinusoid along x of `cycles_per_degree`, measured on its interior (the
// border is a filter radius away) as the least-squares amplitude of the output's oscillation.
double measured_gain(const flip_detail::csf& f, double cycles_per_degree, double ppd) {
    constexpr std::size_t k_width = 200;
    constexpr std::size_t k_border = 11;  // the filter radius at 67 ppd is 10
    plane wave = make_plane(k_width, 3);
    std::vector<double> oscillation(k_width);
    for (std::size_t x = 0; x < k_width; ++x) {
        oscillation[x] =
            10.0 * std::cos(2.0 * std::numbers::pi * cycles_per_degree * double(x) / ppd);
        for (std::size_t y = 0; y < 3; ++y) wave.v[y * k_width + x] = 50.0 + oscillation[x];
    }
    const plane out = flip_detail::filter_csf(wave, f, ppd);
    double along = 0.0, norm = 0.0;
    for (std::size_t x = k_border; x < k_width - k_border; ++x) {
        along += (out.v[k_width + x] - 50.0) * oscillation[x];  // the mean 50 passes with gain 1
        norm += oscillation[x] * oscillation[x];
    }
    return along / norm;
}

TEST(flip_detail, csf_filters_pass_a_sinusoid_with_the_gain_of_the_sum_of_gaussians) {
    // The spatial kernel a sqrt(pi/b) exp(-pi^2 x^2/b) has the Fourier transform a exp(-b f^2).
    // The filter evaluates it at the radius r = |(x, y)|, so each term is separable, and for a
    // sinusoid along x (f_y = 0) its 2D transform is a sqrt(pi/b) * sqrt(b/pi) exp(-b f^2) *
    // sqrt(b/pi) = a sqrt(b/pi) exp(-b f^2); normalised to sum 1 the gain is
    //   (a1 sqrt(b1) exp(-b1 f^2) + a2 sqrt(b2) exp(-b2 f^2)) / (a1 sqrt(b1) + a2 sqrt(b2)).
    // With a2 = 0 (achromatic, red-green) that is exp(-b1 f^2); at 12 cycles per degree:
    //   achromatic exp(-0.0047 * 144) = exp(-0.6768) = 0.508241,
    //   red-green  exp(-0.0053 * 144) = exp(-0.7632) = 0.466172.
    // Blue-yellow at 4 cycles per degree: exp(-0.04 * 16) = 0.527292, exp(-0.025 * 16) = 0.670320,
    //   (34.1 * 0.2 * 0.527292 + 13.5 * 0.158114 * 0.670320) / (6.82 + 2.134539)
    //   = (3.596131 + 1.430774) / 8.954539 = 0.561387.
    // (The 1D CSF's own weights, (34.1 * 0.527292 + 13.5 * 0.670320) / 47.6 = 0.567857, are not
    // what a radially evaluated 2D kernel gives: its terms weigh a sqrt(b), as in the authors'
    // generate_spatial_filter, which this follows.)
    // Tolerances from the sampling at 67 ppd. Achromatic and red-green: sd = sqrt(b / (2 pi^2))
    // * ppd = 1.03 and 1.10 pixels; the radius of 10 pixels cuts nothing (> 9 sd), and the
    // sampled kernel's spectrum repeats every 1 cycle per pixel, the nearest alias adding
    // exp(-b ((1 - 12/67) * 67)^2) = exp(-0.0047 * 55^2) = 6.7e-7 (red-green 1.1e-7): 2e-6.
    // Blue-yellow: sd = 3.02 and 2.38 pixels, so the radius of 10 cuts the wider Gaussian at
    // 3.3 sd, dropping a tail of erfc(10.5 / (3.02 sqrt 2)) = 5.0e-4 of its mass, which moves
    // a normalised gain by at most twice that: 1e-3 (six times less than 0.567857 - 0.561387).
    constexpr double k_ppd = 67.0;
    EXPECT_NEAR(measured_gain(flip_detail::k_csf_achromatic, 12.0, k_ppd), 0.508241, 2e-6);
    EXPECT_NEAR(measured_gain(flip_detail::k_csf_red_green, 12.0, k_ppd), 0.466172, 2e-6);
    EXPECT_NEAR(measured_gain(flip_detail::k_csf_blue_yellow, 4.0, k_ppd), 0.561387, 1e-3);
    // A constant passes unchanged: the filters are normalised to sum 1.
    const plane flat =
        flip_detail::filter_csf(make_plane(30, 30, 42.0), flip_detail::k_csf_blue_yellow, k_ppd);
    for (const double v : flat.v) EXPECT_NEAR(v, 42.0, 1e-12);
}

// The colour error of a pixel whose filtered linear grey is c against black (L* = 0): Hunt's
// a* and b* are 0 for greys, so HyAB = L*(c), and the redistribution of image_metrics_test's
// black-against-white case applies: cmax = 41.276098, pc cmax = 16.510439.
TEST(flip_detail, error_map_of_a_single_bright_pixel_against_black) {
    // At 20 ppd the achromatic CSF's 1D samples are exp(-pi^2 (i/20)^2 / 0.0047): e1 =
    // exp(-5.249790) = 0.0052486 at i = 1, e2 = exp(-21.0) = 7.6e-10, so the sum is
    // S = 1.0104972 and the 2D kernel's centre 1/S^2 = 0.979332. The red-green and blue-yellow
    // channels of black and white are 0, so the filtered pixel is the linear grey 0.979332:
    //   L* = 116 cbrt(0.979332) - 16 = 99.195249, 99.195249^0.7 = 24.977192 > pc cmax, so
    //   dE_c = 0.95 + (24.977192 - 16.510439) / (41.276098 - 16.510439) * 0.05 = 0.967094.
    // Its features (the reference has none): point 0.688038, edge 0 (point_detector test), so
    //   dE_f = (0.688038 / sqrt 2)^0.5 = 0.697507 and dE = 0.967094^(1 - 0.697507) = 0.989930.
    // The pixel to its right: grey e1 / S^2 = 0.0051401, below (6/29)^3, so L* = 116 (0.0051401
    //   / (3 (6/29)^2) + 4/29) - 16 = 4.643071, 4.643071^0.7 = 2.929299 < pc cmax, so dE_c =
    //   0.95 / 16.510439 * 2.929299 = 0.168550; its features: edge 0.397901 > point 0.257304,
    //   dE_f = (0.397901 / sqrt 2)^0.5 = 0.530432, dE = 0.168550^0.469568 = 0.433408.
    // Four pixels away (beyond both radii of 3) both images are black without features: 0.
    image_rgba8 dot = black_image(15, 15);
    paint_white(dot, 7, 7);
    const image_rgba8 black = black_image(15, 15);
    const std::vector<double> map = flip_detail::error_map(black, dot, k_detector_ppd);
    ASSERT_EQ(map.size(), 225u);
    EXPECT_NEAR(map[7 * 15 + 7], 0.989930, 1e-6);
    EXPECT_NEAR(map[7 * 15 + 8], 0.433408, 1e-6);
    EXPECT_NEAR(map[7 * 15 + 6], 0.433408, 1e-6);
    EXPECT_EQ(map[7 * 15 + 11], 0.0);
    EXPECT_EQ(map[0], 0.0);
    // flip_error is the map's mean, and swapping reference and test changes nothing here.
    double sum = 0.0;
    for (const double e : map) sum += e;
    EXPECT_EQ(flip_error(black, dot, k_detector_ppd), sum / 225.0);
    EXPECT_NEAR(flip_error(dot, black, k_detector_ppd), sum / 225.0, 1e-12);
}

TEST(flip_detail, flip_of_a_step_edge_against_its_mirror_image) {
    // Black | white against white | black, the step between columns 9 and 10 of 20. Both have
    // the same edge and point strengths everywhere (a step down is minus a step up, and the
    // detectors take lengths), so dE_f = 0 and dE = dE_c at every pixel. The achromatic CSF
    // (the other channels are 0) reaches 3 columns, with weights 1, e1, e2, e3 / S as above: a
    // column at distance >= 2 from the step keeps black against white to within e2 = 7.6e-10,
    // dE_c = 0.967380 (image_metrics_test). Columns 9 and 10 mix in c = (e1 + e2 + e3) / S =
    // 0.0051941 of the other side: greys c against 1 - c, L* = 116 (c / (3 (6/29)^2) + 4/29)
    // - 16 = 4.691811 and 116 cbrt(0.9948059) - 16 = 99.798813, HyAB = 95.107002,
    // 95.107002^0.7 = 24.252066, dE_c = 0.95 + (24.252066 - 16.510439) / 24.765659 * 0.05
    // = 0.965630. Mean: (18 * 0.967380 + 2 * 0.965630) / 20 = 0.967205.
    image_rgba8 left = black_image(20, 4);
    image_rgba8 right = black_image(20, 4);
    for (std::uint32_t y = 0; y < 4; ++y)
        for (std::uint32_t x = 0; x < 20; ++x) paint_white(x < 10 ? right : left, x, y);
    EXPECT_NEAR(flip_error(left, right, k_detector_ppd), 0.967205, 1e-6);
    const std::vector<double> map = flip_detail::error_map(left, right, k_detector_ppd);
    EXPECT_NEAR(map[9], 0.965630, 1e-6);
    EXPECT_NEAR(map[10], 0.965630, 1e-6);
    EXPECT_NEAR(map[7], 0.967380, 1e-6);
}

}  // namespace
}  // namespace sylva
