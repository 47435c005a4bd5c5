#include "app/rung_colours.h"

#include <algorithm>

namespace sylva {

image_rgba8 tint_by_rung(const image_rgba8& image, std::span<const std::uint32_t> ids,
                         std::span<const lod_state> lods) {
    std::array<std::array<std::uint8_t, 3>, std::size_t(representation::count)> colour_of{};
    for (const rung_colour& c : k_rung_colours) colour_of[std::size_t(c.rung)] = c.rgb;
    image_rgba8 out = image;
    const std::size_t pixels = std::min(ids.size(), std::size_t(image.width) * image.height);
    for (std::size_t i = 0; i < pixels; ++i) {
        std::uint8_t* p = &out.texels[4 * i];
        const int luma = (p[0] * 54 + p[1] * 183 + p[2] * 19) >> 8;  // Rec. 709 weights, of 256
        const std::uint32_t id = ids[i];
        if (id == 0 || id > lods.size()) {
            for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(p[c] / 2);  // not a plant: dimmed
            continue;
        }
        const auto& rgb = colour_of[std::size_t(lods[id - 1].current)];
        // 0.4 .. 1 of the rung's colour by the pixel's brightness.
        for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(rgb[std::size_t(c)] * (102 + luma * 153 / 255) / 255);
    }
    return out;
}

}  // namespace sylva
