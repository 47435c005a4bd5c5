#pragma once
// Golden-image comparison helpers: images are compared with a tolerance (the rasteriser may
// differ in the last bit between Mesa builds), and SYLVA_UPDATE_GOLDEN=1 rewrites the goldens.
#include <cmath>
#include <cstdint>

#include "models/image.h"

namespace sylva::testing {

struct image_difference {
    double mean_absolute = 0.0;  // per channel, 0..255
    double max_absolute = 0.0;
    double psnr_db = 0.0;        // RGB, peak 255; infinity when identical
    double fraction_over_16 = 0.0;  // fraction of pixels with any channel off by more than 16
};

inline image_difference compare_images(const image_rgba8& a, const image_rgba8& b) {
    image_difference d;
    if (a.width != b.width || a.height != b.height) {
        d.mean_absolute = d.max_absolute = 255.0;
        d.fraction_over_16 = 1.0;
        return d;
    }
    double sum = 0.0, squared = 0.0;
    std::size_t over = 0;
    const std::size_t pixels = std::size_t(a.width) * a.height;
    for (std::size_t p = 0; p < pixels; ++p) {
        bool pixel_over = false;
        for (int c = 0; c < 3; ++c) {
            const double diff = std::abs(double(a.texels[p * 4 + c]) - double(b.texels[p * 4 + c]));
            sum += diff;
            squared += diff * diff;
            d.max_absolute = std::max(d.max_absolute, diff);
            pixel_over = pixel_over || diff > 16.0;
        }
        over += pixel_over ? 1 : 0;
    }
    d.mean_absolute = sum / double(pixels * 3);
    const double mse = squared / double(pixels * 3);
    d.psnr_db = mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : INFINITY;
    d.fraction_over_16 = double(over) / double(pixels);
    return d;
}

}  // namespace sylva::testing
