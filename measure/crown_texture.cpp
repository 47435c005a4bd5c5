#include "measure/crown_texture.h"

#include <stdexcept>

namespace sylva {

std::vector<std::uint8_t> mask_interior(const std::vector<std::uint8_t>& mask, std::uint32_t width,
                                        std::uint32_t height, std::uint32_t radius) {
    if (mask.size() != std::size_t(width) * height)
        throw std::invalid_argument("mask_interior: the mask is not width x height");
    std::vector<std::uint8_t> out(mask.size(), 0);
    const auto r = std::int64_t(radius);
    for (std::int64_t y = r; y + r < std::int64_t(height); ++y)
        for (std::int64_t x = r; x + r < std::int64_t(width); ++x) {
            bool all = true;
            for (std::int64_t dy = -r; dy <= r && all; ++dy)
                for (std::int64_t dx = -r; dx <= r && all; ++dx)
                    all = mask[std::size_t((y + dy) * width + (x + dx))] != 0;
            out[std::size_t(y * width + x)] = all ? 1 : 0;
        }
    return out;
}

crown_texture crown_texture_of(const image_rgba8& image, const std::vector<std::uint8_t>& interior) {
    const std::size_t w = image.width, h = image.height;
    if (interior.size() != w * h) throw std::invalid_argument("crown_texture_of: the mask is not the image's size");
    const auto luma = [&](std::size_t x, std::size_t y) {
        const std::uint8_t* p = &image.texels[4 * (y * w + x)];
        return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    };
    crown_texture out;
    double sum = 0.0, lap_sum = 0.0, lap_squares = 0.0;
    for (std::size_t y = 1; y + 1 < h; ++y)
        for (std::size_t x = 1; x + 1 < w; ++x) {
            if (!interior[y * w + x]) continue;
            const double l = luma(x, y);
            const double lap = 4.0 * l - luma(x - 1, y) - luma(x + 1, y) - luma(x, y - 1) - luma(x, y + 1);
            ++out.pixels;
            sum += l;
            lap_sum += lap;
            lap_squares += lap * lap;
        }
    if (out.pixels == 0) return out;
    const double n = double(out.pixels);
    out.mean_luma = sum / n;
    out.mean_laplacian = lap_sum / n;
    out.laplacian_variance = lap_squares / n - out.mean_laplacian * out.mean_laplacian;
    return out;
}

crown_texture pooled(const crown_texture& a, const crown_texture& b) {
    if (a.pixels == 0) return b;
    if (b.pixels == 0) return a;
    crown_texture out;
    out.pixels = a.pixels + b.pixels;
    const double wa = double(a.pixels) / double(out.pixels), wb = 1.0 - wa;
    out.mean_luma = wa * a.mean_luma + wb * b.mean_luma;
    out.mean_laplacian = wa * a.mean_laplacian + wb * b.mean_laplacian;
    // E[X²] pooled, less the pooled mean squared.
    const double second = wa * (a.laplacian_variance + a.mean_laplacian * a.mean_laplacian) +
                          wb * (b.laplacian_variance + b.mean_laplacian * b.mean_laplacian);
    out.laplacian_variance = second - out.mean_laplacian * out.mean_laplacian;
    return out;
}

}  // namespace sylva
