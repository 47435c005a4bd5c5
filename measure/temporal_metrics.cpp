#include "measure/temporal_metrics.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sylva {
namespace {

void require_same_size(const image_rgba8& a, const image_rgba8& b, const char* what) {
    if (a.width != b.width || a.height != b.height || a.texels.size() != b.texels.size())
        throw std::invalid_argument(std::string(what) + ": image sizes differ (" + std::to_string(a.width) + "x" +
                                    std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                                    std::to_string(b.height) + ")");
}

// Rec. 709 luma of a stored texel, 8-bit units.
double luma(const std::uint8_t* t) { return 0.2126 * t[0] + 0.7152 * t[1] + 0.0722 * t[2]; }

}  // namespace

double popping_score(const image_rgba8& test, const image_rgba8& test_previous, const image_rgba8& reference,
                     const image_rgba8& reference_previous) {
    require_same_size(test, test_previous, "popping_score");
    require_same_size(test, reference, "popping_score");
    require_same_size(test, reference_previous, "popping_score");
    const std::size_t pixels = std::size_t(test.width) * test.height;
    if (pixels == 0) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::size_t o = i * 4;
        const double e_now = luma(&test.texels[o]) - luma(&reference.texels[o]);
        const double e_before = luma(&test_previous.texels[o]) - luma(&reference_previous.texels[o]);
        sum += std::abs(e_now - e_before);
    }
    return sum / double(pixels);
}

plant_colors mean_plant_colors(const image_rgba8& image, const std::vector<std::uint32_t>& ids) {
    if (ids.size() != std::size_t(image.width) * image.height)
        throw std::invalid_argument("mean_plant_colors: " + std::to_string(ids.size()) + " IDs for a " +
                                    std::to_string(image.width) + "x" + std::to_string(image.height) + " image");
    plant_colors colors;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (ids[i] == 0) continue;
        plant_color& c = colors[ids[i]];
        c.r += image.texels[i * 4];
        c.g += image.texels[i * 4 + 1];
        c.b += image.texels[i * 4 + 2];
        ++c.pixels;
    }
    for (auto& [id, c] : colors) {
        c.r /= c.pixels;
        c.g /= c.pixels;
        c.b /= c.pixels;
    }
    return colors;
}

double lighting_jump(const plant_color& test_before, const plant_color& test_after, const plant_color& reference_before,
                     const plant_color& reference_after) {
    const double dr = (test_after.r - test_before.r) - (reference_after.r - reference_before.r);
    const double dg = (test_after.g - test_before.g) - (reference_after.g - reference_before.g);
    const double db = (test_after.b - test_before.b) - (reference_after.b - reference_before.b);
    return std::sqrt(dr * dr + dg * dg + db * db);
}

std::vector<std::uint8_t> plant_mask(const std::vector<std::uint32_t>& ids) {
    std::vector<std::uint8_t> mask(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) mask[i] = ids[i] != 0 ? 1 : 0;
    return mask;
}

}  // namespace sylva
