#include "models/image/image_ops.h"

#include <stdexcept>
#include <string>

namespace sylva {

image_rgba8 box_downsample(const image_rgba8& image, std::uint32_t factor) {
    if (factor == 0 || image.width % factor || image.height % factor)
        throw std::invalid_argument("box_downsample: " + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + " is not a multiple of " + std::to_string(factor));
    image_rgba8 out;
    out.width = image.width / factor;
    out.height = image.height / factor;
    out.texels.resize(std::size_t(out.width) * out.height * 4);
    const std::uint32_t samples = factor * factor;
    for (std::uint32_t y = 0; y < out.height; ++y)
        for (std::uint32_t x = 0; x < out.width; ++x)
            for (int c = 0; c < 4; ++c) {
                std::uint32_t sum = 0;
                for (std::uint32_t sy = 0; sy < factor; ++sy)
                    for (std::uint32_t sx = 0; sx < factor; ++sx) sum += image.at(x * factor + sx, y * factor + sy)[c];
                out.at(x, y)[c] = std::uint8_t((sum + samples / 2) / samples);
            }
    return out;
}

image_rgba8 replicate_upsample(const image_rgba8& image, std::uint32_t factor) {
    if (factor == 0) throw std::invalid_argument("replicate_upsample: factor must be at least 1");
    image_rgba8 out;
    out.width = image.width * factor;
    out.height = image.height * factor;
    out.texels.resize(std::size_t(out.width) * out.height * 4);
    for (std::uint32_t y = 0; y < out.height; ++y)
        for (std::uint32_t x = 0; x < out.width; ++x)
            for (int c = 0; c < 4; ++c) out.at(x, y)[c] = image.at(x / factor, y / factor)[c];
    return out;
}

}  // namespace sylva
