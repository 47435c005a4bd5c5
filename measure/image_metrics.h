#pragma once
// Image error metrics between two frames of the same size (a test frame against a reference):
// RMSE and PSNR, mean SSIM on luminance, a FLIP perceptual difference, and plant-mask
// intersection over union. Pure CPU, deterministic (no threads, no randomness).
//
// Texels are read as stored 8-bit values scaled to 0..1 (value / 255); alpha is ignored by every
// metric. Every function taking two images throws std::invalid_argument naming both sizes when
// they differ.
#include <cstdint>
#include <vector>

#include "models/image/image.h"

namespace sylva {

// Root mean square error over the R, G and B channels of every pixel, in 0..1 units:
// sqrt(sum (a - b)^2 / (3 * width * height)). 0 for two empty images.
double rmse(const image_rgba8& a, const image_rgba8& b);

// Peak signal-to-noise ratio in dB with a peak of 1: 20 * log10(1 / rmse(a, b)); +infinity when
// the RGB channels are identical. This is the definition OpenImageIO's `oiiotool --diff` prints
// as "Peak SNR" when given the same (RGB) channels; note that on RGBA files oiiotool averages
// over all four channels, alpha included.
double psnr_db(const image_rgba8& a, const image_rgba8& b);

// Mean SSIM (Wang, Bovik, Sheikh, Simoncelli 2004) of the luminance Y = 0.2126 R + 0.7152 G +
// 0.0722 B of the stored values, with an 11x11 Gaussian window (sigma 1.5), K1 = 0.01,
// K2 = 0.03, L = 1. Averaged over the pixels whose whole window lies inside the image (the
// "valid" convention of the authors' ssim_index.m; no borders are invented and the image is not
// downsampled first). 1 for identical images. Throws std::invalid_argument if either side is
// smaller than 11 pixels.
double mean_ssim(const image_rgba8& a, const image_rgba8& b);

// The SSIM of every window mean_ssim averages: (width − 10) x (height − 10) values, row by row,
// the value at (x, y) that of the window whose top-left pixel is (x, y), so centred on pixel
// (x + 5, y + 5). mean_ssim is their mean. Throws as mean_ssim does.
struct ssim_windows {
    std::size_t width = 0, height = 0;
    std::vector<double> values;
};
ssim_windows ssim_map(const image_rgba8& a, const image_rgba8& b);

// LDR-FLIP (Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom, Fairchild 2020, "FLIP: A
// Difference Evaluator for Alternating Images"), pooled as the mean over pixels, in 0..1 (0 for
// identical images). `a` is the reference, `b` the test; both are read as sRGB-encoded display
// values. `pixels_per_degree` is the observer's angular resolution (the paper's default setup,
// a 0.7 m wide 4K monitor at 0.7 m, gives about 67). See measure/flip_error.cpp for the
// pipeline and what it leaves out. Throws std::invalid_argument if pixels_per_degree <= 0.
double flip_error(const image_rgba8& a, const image_rgba8& b, double pixels_per_degree);

// Intersection over union of the nonzero entries of two masks of the same length (e.g. plant
// IDs per pixel, 0 = no plant): |a and b| / |a or b|; 1 when both masks are empty. Throws
// std::invalid_argument when the lengths differ.
double coverage_iou(const std::vector<std::uint8_t>& mask_a, const std::vector<std::uint8_t>& mask_b);

}  // namespace sylva
