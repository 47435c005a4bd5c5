#include "lod/shell_canopy.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sylva {

std::vector<image_rgba8> with_canopy_transmittance(std::vector<image_rgba8> normal, std::span<const image_rgba8> colour) {
    if (normal.size() != colour.size())
        throw std::invalid_argument("with_canopy_transmittance: " + std::to_string(normal.size()) + " normal slices for " +
                                    std::to_string(colour.size()) + " colour slices");
    if (normal.empty()) return normal;
    const std::size_t texels = colour.back().texels.size();
    for (std::size_t k = 0; k < normal.size(); ++k)
        if (normal[k].texels.size() != texels || colour[k].texels.size() != texels)
            throw std::invalid_argument("with_canopy_transmittance: slice " + std::to_string(k) + " differs in size");
    // Top down, the product of (1 − α) of the slices above, kept in float so 8-bit rounding
    // happens once per texel.
    std::vector<float> above(texels / 4, 1.0f);
    for (std::size_t k = normal.size(); k-- > 0;) {
        std::vector<std::uint8_t>& out = normal[k].texels;
        const std::vector<std::uint8_t>& alpha = colour[k].texels;
        for (std::size_t i = 0; i < above.size(); ++i) {
            out[i * 4 + 3] = std::uint8_t(std::lround(std::clamp(above[i], 0.0f, 1.0f) * 255.0f));
            above[i] *= 1.0f - float(alpha[i * 4 + 3]) / 255.0f;
        }
    }
    return normal;
}

}  // namespace sylva
