#include "measure/image_metrics.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

#include "measure/image_checks.h"

namespace sylva {

namespace {

std::string size_text(const image_rgba8& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

std::size_t pixel_count(const image_rgba8& image) { return std::size_t(image.width) * image.height; }

// Rec. 709 luma of the stored values, 0..1 (no sRGB decoding: SSIM compares code values).
std::vector<double> luminance(const image_rgba8& image) {
    std::vector<double> y(pixel_count(image));
    for (std::size_t i = 0; i < y.size(); ++i) {
        const std::uint8_t* t = &image.texels[i * 4];
        y[i] = (0.2126 * t[0] + 0.7152 * t[1] + 0.0722 * t[2]) / 255.0;
    }
    return y;
}

constexpr int k_ssim_window = 11;
constexpr double k_ssim_sigma = 1.5;

// The 1D Gaussian of the SSIM window, normalised to sum 1; the 2D window (the w_i of Eq. 14-16)
// is its outer product with itself, which then also sums to 1.
std::array<double, k_ssim_window> ssim_weights() {
    std::array<double, k_ssim_window> w{};
    double sum = 0.0;
    for (int i = 0; i < k_ssim_window; ++i) {
        const double x = i - k_ssim_window / 2;
        w[std::size_t(i)] = std::exp(-x * x / (2.0 * k_ssim_sigma * k_ssim_sigma));
        sum += w[std::size_t(i)];
    }
    for (double& v : w) v /= sum;
    return w;
}

// Separable "valid" filtering: out is (width - 10) x (height - 10), out(x, y) the weighted mean
// of the 11x11 window whose top-left corner is (x, y).
std::vector<double> filter_valid(const std::vector<double>& in, std::size_t width, std::size_t height) {
    static const std::array<double, k_ssim_window> w = ssim_weights();
    const std::size_t n = k_ssim_window;
    const std::size_t out_w = width - n + 1;
    const std::size_t out_h = height - n + 1;
    std::vector<double> rows(out_w * height);
    for (std::size_t y = 0; y < height; ++y)
        for (std::size_t x = 0; x < out_w; ++x) {
            double s = 0.0;
            for (std::size_t k = 0; k < n; ++k) s += w[k] * in[y * width + x + k];
            rows[y * out_w + x] = s;
        }
    std::vector<double> out(out_w * out_h);
    for (std::size_t y = 0; y < out_h; ++y)
        for (std::size_t x = 0; x < out_w; ++x) {
            double s = 0.0;
            for (std::size_t k = 0; k < n; ++k) s += w[k] * rows[(y + k) * out_w + x];
            out[y * out_w + x] = s;
        }
    return out;
}

}  // namespace

void require_same_size(const image_rgba8& a, const image_rgba8& b, const char* metric) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument(std::string(metric) + ": image sizes differ (" + size_text(a) + " vs " +
                                    size_text(b) + ")");
    if (a.texels.size() != pixel_count(a) * 4 || b.texels.size() != pixel_count(b) * 4)
        throw std::invalid_argument(std::string(metric) + ": texel count does not match the image size " +
                                    size_text(a));
}

double rmse(const image_rgba8& a, const image_rgba8& b) {
    require_same_size(a, b, "rmse");
    const std::size_t pixels = pixel_count(a);
    if (pixels == 0) return 0.0;
    // Integer sum of squared code-value differences: exact, so the result does not depend on
    // summation order.
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < pixels; ++i)
        for (std::size_t c = 0; c < 3; ++c) {
            const int d = int(a.texels[i * 4 + c]) - int(b.texels[i * 4 + c]);
            sum += std::uint64_t(d * d);
        }
    return std::sqrt(double(sum) / double(pixels * 3)) / 255.0;
}

double psnr_db(const image_rgba8& a, const image_rgba8& b) {
    const double error = rmse(a, b);
    if (error == 0.0) return std::numeric_limits<double>::infinity();
    return 20.0 * std::log10(1.0 / error);
}

ssim_windows ssim_map(const image_rgba8& a, const image_rgba8& b) {
    require_same_size(a, b, "mean_ssim");
    if (a.width < k_ssim_window || a.height < k_ssim_window)
        throw std::invalid_argument("mean_ssim: image " + size_text(a) + " is smaller than the 11x11 window");
    const std::size_t width = a.width;
    const std::size_t height = a.height;
    const std::vector<double> ya = luminance(a);
    const std::vector<double> yb = luminance(b);
    std::vector<double> aa(ya.size()), bb(ya.size()), ab(ya.size());
    for (std::size_t i = 0; i < ya.size(); ++i) {
        aa[i] = ya[i] * ya[i];
        bb[i] = yb[i] * yb[i];
        ab[i] = ya[i] * yb[i];
    }
    // Local statistics with the Gaussian window w (Eq. 14-16): mu = sum w x,
    // sigma^2 = sum w x^2 - mu^2, sigma_ab = sum w x y - mu_a mu_b.
    const std::vector<double> mu_a = filter_valid(ya, width, height);
    const std::vector<double> mu_b = filter_valid(yb, width, height);
    const std::vector<double> e_aa = filter_valid(aa, width, height);
    const std::vector<double> e_bb = filter_valid(bb, width, height);
    const std::vector<double> e_ab = filter_valid(ab, width, height);

    // C1 = (K1 L)^2 (Eq. 7), C2 = (K2 L)^2 (Eq. 9), with L = 1 for values in 0..1.
    constexpr double c1 = (0.01 * 1.0) * (0.01 * 1.0);
    constexpr double c2 = (0.03 * 1.0) * (0.03 * 1.0);
    const std::size_t window = std::size_t(k_ssim_window);
    ssim_windows out{width - window + 1, height - window + 1, std::vector<double>(mu_a.size())};
    for (std::size_t i = 0; i < mu_a.size(); ++i) {
        const double ma = mu_a[i];
        const double mb = mu_b[i];
        const double var_a = e_aa[i] - ma * ma;
        const double var_b = e_bb[i] - mb * mb;
        const double cov = e_ab[i] - ma * mb;
        // SSIM(x, y) = (2 mu_x mu_y + C1)(2 sigma_xy + C2) /
        //              ((mu_x^2 + mu_y^2 + C1)(sigma_x^2 + sigma_y^2 + C2))   (Eq. 13)
        out.values[i] = ((2.0 * ma * mb + c1) * (2.0 * cov + c2)) / ((ma * ma + mb * mb + c1) * (var_a + var_b + c2));
    }
    return out;
}

double mean_ssim(const image_rgba8& a, const image_rgba8& b) {
    const ssim_windows map = ssim_map(a, b);
    // MSSIM = (1/M) sum_j SSIM(x_j, y_j) over the M window positions (Eq. 17).
    double sum = 0.0;
    for (const double v : map.values) sum += v;
    return sum / double(map.values.size());
}

double coverage_iou(const std::vector<std::uint8_t>& mask_a, const std::vector<std::uint8_t>& mask_b) {
    if (mask_a.size() != mask_b.size())
        throw std::invalid_argument("coverage_iou: mask sizes differ (" + std::to_string(mask_a.size()) + " vs " +
                                    std::to_string(mask_b.size()) + ")");
    std::size_t intersection = 0;
    std::size_t united = 0;
    for (std::size_t i = 0; i < mask_a.size(); ++i) {
        const bool in_a = mask_a[i] != 0;
        const bool in_b = mask_b[i] != 0;
        intersection += (in_a && in_b) ? 1 : 0;
        united += (in_a || in_b) ? 1 : 0;
    }
    if (united == 0) return 1.0;
    return double(intersection) / double(united);
}

}  // namespace sylva
