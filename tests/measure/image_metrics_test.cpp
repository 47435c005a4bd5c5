#include "measure/image_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/generate/textures.h"

namespace sylva {
namespace {

image_rgba8 constant_image(std::uint32_t width, std::uint32_t height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    image_rgba8 image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
    for (std::size_t i = 0; i < std::size_t(width) * height; ++i) {
        image.texels[i * 4 + 0] = r;
        image.texels[i * 4 + 1] = g;
        image.texels[i * 4 + 2] = b;
        image.texels[i * 4 + 3] = 255;
    }
    return image;
}

// A deterministic value in [-1, 1] per (x, y, channel): an integer hash, no <random> engines.
double noise(std::uint32_t x, std::uint32_t y, std::uint32_t c) {
    std::uint32_t h = x * 73856093u ^ y * 19349663u ^ c * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return double(h % 2001u) / 1000.0 - 1.0;
}

// Smooth gradients plus a checker pattern, every channel within 60..190 so that added noise up to
// +-60 never clamps.
image_rgba8 textured_image(std::uint32_t width, std::uint32_t height) {
    image_rgba8 image = constant_image(width, height, 0, 0, 0);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            std::uint8_t* t = image.at(x, y);
            const std::uint32_t checker = ((x / 4 + y / 4) % 2) * 30;
            t[0] = std::uint8_t(60 + (x * 90) / width + checker);
            t[1] = std::uint8_t(60 + (y * 90) / height + checker);
            t[2] = std::uint8_t(60 + ((x + y) * 45) / (width + height) + checker);
        }
    return image;
}

image_rgba8 add_noise(const image_rgba8& image, double amplitude) {
    image_rgba8 out = image;
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x)
            for (std::uint32_t c = 0; c < 3; ++c) {
                const double v = std::round(image.at(x, y)[c] + amplitude * noise(x, y, c));
                out.at(x, y)[c] = std::uint8_t(std::clamp(v, 0.0, 255.0));
            }
    return out;
}

TEST(image_metrics, identical_images_have_zero_error) {
    const image_rgba8 a = textured_image(32, 24);
    EXPECT_EQ(rmse(a, a), 0.0);
    EXPECT_EQ(psnr_db(a, a), std::numeric_limits<double>::infinity());
    EXPECT_NEAR(mean_ssim(a, a), 1.0, 1e-12);
    EXPECT_EQ(flip_error(a, a, 67.0), 0.0);
}

TEST(image_metrics, one_channel_offset_by_one_code_value) {
    // Green + 1/255 everywhere: MSE over RGB = (1/255)^2 / 3, so RMSE = 1 / (255 sqrt 3)
    // = 0.0022641187 and PSNR = 20 log10(255 sqrt 3) = 48.1308 + 4.7712 = 52.9020162 dB.
    const image_rgba8 a = constant_image(7, 5, 10, 100, 200);
    const image_rgba8 b = constant_image(7, 5, 10, 101, 200);
    EXPECT_NEAR(rmse(a, b), 0.0022641187027, 1e-12);
    EXPECT_NEAR(psnr_db(a, b), 52.9020161559, 1e-9);
}

TEST(image_metrics, ssim_of_constant_images_is_the_luminance_term) {
    // Both variances and the covariance are 0, so the contrast-structure factor is C2 / C2 = 1 and
    // SSIM = (2 mu_a mu_b + C1) / (mu_a^2 + mu_b^2 + C1) with mu_a = 100/255, mu_b = 150/255,
    // C1 = 1e-4: (0.4613610 + 0.0001) / (0.4998078 + 0.0001) = 0.9230923105.
    const image_rgba8 a = constant_image(16, 16, 100, 100, 100);
    const image_rgba8 b = constant_image(16, 16, 150, 150, 150);
    EXPECT_NEAR(mean_ssim(a, b), 0.923092310531, 1e-9);
}

TEST(image_metrics, ssim_map_holds_one_value_per_window_centred_on_its_pixel) {
    // 16 x 13 pixels: 6 x 3 windows of 11 x 11. The left half 100 in one image and 150 in the
    // other, the right half equal: a window wholly within the equal half is 1; the windows
    // reaching into the left half are less.
    image_rgba8 a = constant_image(16, 13, 100, 100, 100), b = a;
    for (std::uint32_t y = 0; y < 13; ++y)
        for (std::uint32_t x = 0; x < 3; ++x) b.at(x, y)[0] = b.at(x, y)[1] = b.at(x, y)[2] = 150;
    const ssim_windows map = ssim_map(a, b);
    ASSERT_EQ(map.width, 6u);
    ASSERT_EQ(map.height, 3u);
    ASSERT_EQ(map.values.size(), 18u);
    // The window at x = 3 covers pixels 3..13: none of the changed columns 0..2.
    for (std::size_t y = 0; y < 3; ++y) {
        EXPECT_LT(map.values[y * 6 + 0], 1.0);
        EXPECT_LT(map.values[y * 6 + 2], 1.0);
        EXPECT_NEAR(map.values[y * 6 + 3], 1.0, 1e-12);
        EXPECT_NEAR(map.values[y * 6 + 5], 1.0, 1e-12);
    }
    double sum = 0.0;
    for (const double v : map.values) sum += v;
    EXPECT_DOUBLE_EQ(mean_ssim(a, b), sum / 18.0);  // the mean of the map
    // Constant halves: each window's value is the luminance term of the previous test's shape.
    const ssim_windows whole = ssim_map(constant_image(11, 11, 100, 100, 100), constant_image(11, 11, 150, 150, 150));
    ASSERT_EQ(whole.values.size(), 1u);
    EXPECT_NEAR(whole.values[0], 0.923092310531, 1e-9);
}

TEST(image_metrics, ssim_decreases_monotonically_with_noise) {
    const image_rgba8 a = textured_image(64, 48);
    double previous = mean_ssim(a, a);
    for (const double amplitude : {4.0, 8.0, 16.0, 32.0, 60.0}) {
        const double ssim = mean_ssim(a, add_noise(a, amplitude));
        EXPECT_LT(ssim, previous) << "amplitude " << amplitude;
        EXPECT_GT(ssim, 0.0) << "amplitude " << amplitude;
        previous = ssim;
    }
}

TEST(image_metrics, flip_of_black_against_white_is_the_redistributed_colour_error) {
    // Constant images: the CSF filters keep the colour, the feature detectors see nothing, so
    // dE = dE_c. Black is L*a*b* (0, 0, 0), white (100, 0, 0): HyAB = 100, 100^0.7 = 25.1189.
    // cmax: Hunt-adjusted green (87.7362, -75.6099, 72.9812), blue (32.2982, 25.5781, -34.8364),
    // HyAB = 55.4380 + 147.8637 = 203.3017, ^0.7 = 41.2761, pc cmax = 16.5104, so
    // dE_c = 0.95 + (25.1189 - 16.5104) / (41.2761 - 16.5104) * 0.05 = 0.967380.
    const image_rgba8 black = constant_image(12, 10, 0, 0, 0);
    const image_rgba8 white = constant_image(12, 10, 255, 255, 255);
    EXPECT_NEAR(flip_error(black, white, 67.0), 0.967380, 1e-5);
    EXPECT_NEAR(flip_error(white, black, 67.0), 0.967380, 1e-5);
}

TEST(image_metrics, flip_grows_with_noise_and_stays_in_unit_range) {
    const image_rgba8 a = textured_image(48, 40);
    double previous = 0.0;
    for (const double amplitude : {4.0, 16.0, 60.0}) {
        const double error = flip_error(a, add_noise(a, amplitude), 67.0);
        EXPECT_GT(error, previous) << "amplitude " << amplitude;
        EXPECT_LE(error, 1.0);
        previous = error;
    }
    EXPECT_THROW(flip_error(a, a, 0.0), std::invalid_argument);
}

TEST(image_metrics, coverage_iou_hand_values) {
    EXPECT_EQ(coverage_iou({}, {}), 1.0);
    EXPECT_EQ(coverage_iou({0, 0, 0}, {0, 0, 0}), 1.0);
    EXPECT_EQ(coverage_iou({1, 0, 0}, {0, 0, 0}), 0.0);
    // Covered indices: a = {0, 1, 2}, b = {1, 2, 3}; intersection {1, 2} = 2, union {0..3} = 4.
    EXPECT_EQ(coverage_iou({1, 1, 7, 0, 0}, {0, 3, 1, 9, 0}), 0.5);
    // Any nonzero value counts as covered: 3 of 3.
    EXPECT_EQ(coverage_iou({1, 2, 3}, {255, 9, 1}), 1.0);
    // Intersection 1, union 3.
    EXPECT_DOUBLE_EQ(coverage_iou({1, 1, 0}, {0, 1, 1}), 1.0 / 3.0);
    EXPECT_THROW(coverage_iou({1}, {1, 0}), std::invalid_argument);
}

TEST(image_metrics, size_mismatch_throws_naming_both_sizes) {
    const image_rgba8 a = constant_image(16, 12, 0, 0, 0);
    const image_rgba8 b = constant_image(12, 16, 0, 0, 0);
    try {
        rmse(a, b);
        FAIL() << "rmse accepted images of different sizes";
    } catch (const std::invalid_argument& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("16x12"), std::string::npos) << message;
        EXPECT_NE(message.find("12x16"), std::string::npos) << message;
    }
    EXPECT_THROW(psnr_db(a, b), std::invalid_argument);
    EXPECT_THROW(mean_ssim(a, b), std::invalid_argument);
    EXPECT_THROW(flip_error(a, b, 67.0), std::invalid_argument);
    EXPECT_THROW(mean_ssim(constant_image(10, 40, 0, 0, 0), constant_image(10, 40, 0, 0, 0)), std::invalid_argument);
}

// --- Cross-check against OpenImageIO's oiiotool (a tool we did not write) ---

// Runs a shell command and returns its standard output.
std::string run(const std::string& command) {
    std::string output;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return output;
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
    pclose(pipe);
    return output;
}

// The number after "Peak SNR = " in an `oiiotool --diff` report, or NaN.
double peak_snr(const std::string& report) {
    const std::string key = "Peak SNR = ";
    const std::size_t at = report.find(key);
    if (at == std::string::npos) return std::nan("");
    return std::strtod(report.c_str() + at + key.size(), nullptr);
}

TEST(image_metrics, psnr_matches_oiiotool_diff) {
    if (std::system("command -v oiiotool > /dev/null 2>&1") != 0)
        GTEST_SKIP() << "oiiotool (OpenImageIO tools) is not on PATH; install openimageio-tools";
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("sylva_measure_oiiotool_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                       "_" + std::to_string(std::uintptr_t(&dir)));
    std::filesystem::create_directories(dir);
    const image_rgba8 a = textured_image(64, 48);
    for (const double amplitude : {3.0, 20.0}) {
        const image_rgba8 b = add_noise(a, amplitude);
        const std::filesystem::path pa = dir / "a.png";
        const std::filesystem::path pb = dir / "b.png";
        write_image(a, pa);
        write_image(b, pb);
        const double ours = psnr_db(a, b);
        // oiiotool averages over every channel of the files; restricted to R, G, B it computes
        // exactly our definition, 20 log10(1 / RMSE).
        const std::string rgb = run("oiiotool \"" + pa.string() + "\" --ch R,G,B \"" + pb.string() +
                                    "\" --ch R,G,B --diff 2>&1");
        EXPECT_NEAR(ours, peak_snr(rgb), 0.01) << "amplitude " << amplitude << "\n" << rgb;
        // On the RGBA files, alpha (255 in both) adds a fourth channel with zero error:
        // MSE_rgba = 3/4 MSE_rgb, so oiiotool's PSNR is ours + 10 log10(4/3).
        const std::string rgba = run("oiiotool \"" + pa.string() + "\" \"" + pb.string() + "\" --diff 2>&1");
        EXPECT_NEAR(ours + 10.0 * std::log10(4.0 / 3.0), peak_snr(rgba), 0.01) << "amplitude " << amplitude << "\n"
                                                                                << rgba;
        std::printf("amplitude %.0f: sylva PSNR %.4f dB, oiiotool RGB %.4f dB, RGBA %.4f dB\n", amplitude, ours,
                    peak_snr(rgb), peak_snr(rgba));
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sylva
