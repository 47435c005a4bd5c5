#include "models/image/texture_sampling.h"

#include <algorithm>
#include <cmath>

namespace sylva {

std::uint32_t wrap_texel(std::int32_t i, std::uint32_t size) {
    if ((size & (size - 1)) == 0) return std::uint32_t(i) & (size - 1);  // power of two
    const auto n = std::int32_t(size);
    const std::int32_t m = i % n;
    return std::uint32_t(m < 0 ? m + n : m);
}

bilinear_footprint footprint(const image_rgba8& texture, glm::vec2 uv) {
    // Clamped far beyond any sensible tiling so the integer conversion is defined.
    constexpr float k_limit = 1e8f;
    const float x = std::clamp(uv.x * float(texture.width) - 0.5f, -k_limit, k_limit);
    const float y = std::clamp(uv.y * float(texture.height) - 0.5f, -k_limit, k_limit);
    const float fx = std::floor(x);
    const float fy = std::floor(y);
    const float tx = x - fx;
    const float ty = y - fy;
    const std::uint32_t x0 = wrap_texel(std::int32_t(fx), texture.width);
    const std::uint32_t x1 = wrap_texel(std::int32_t(fx) + 1, texture.width);
    const std::uint32_t y0 = wrap_texel(std::int32_t(fy), texture.height);
    const std::uint32_t y1 = wrap_texel(std::int32_t(fy) + 1, texture.height);
    return {{texture.at(x0, y0), texture.at(x1, y0), texture.at(x0, y1), texture.at(x1, y1)},
            {(1.0f - tx) * (1.0f - ty), tx * (1.0f - ty), (1.0f - tx) * ty, tx * ty}};
}

float bilinear_alpha(const image_rgba8& texture, glm::vec2 uv) {
    const bilinear_footprint f = footprint(texture, uv);
    float a = 0.0f;
    for (int i = 0; i < 4; ++i) a += f.weight[i] * float(f.texel[i][3]);
    return a;
}

glm::vec3 bilinear_colour(const image_rgba8& texture, glm::vec2 uv, bool alpha_weighted) {
    const bilinear_footprint f = footprint(texture, uv);
    glm::vec3 sum{0.0f};
    float total = 0.0f;
    for (int i = 0; i < 4; ++i) {
        const float w = alpha_weighted ? f.weight[i] * float(f.texel[i][3]) : f.weight[i];
        sum += w * glm::vec3(f.texel[i][0], f.texel[i][1], f.texel[i][2]);
        total += w;
    }
    return total > 0.0f ? sum / total : sum;
}

}  // namespace sylva
