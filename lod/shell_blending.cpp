#include "lod/shell_blending.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/bake/shell_bake.h"
#include "models/bake/transfer_pages.h"

namespace sylva {

glm::vec4 premultiply(const glm::vec4& straight) {
    return {straight.r * straight.a, straight.g * straight.a, straight.b * straight.a, straight.a};
}

glm::vec4 blend_standard(const glm::vec4& c, const glm::vec4& frame) { return c * c.a + frame * (1.0f - c.a); }

glm::vec4 blend_premultiplied(const glm::vec4& c, const glm::vec4& frame) { return c + frame * (1.0f - c.a); }

image_rgba8 merge_slices(const image_rgba8& lower, const image_rgba8& upper) {
    if (lower.width != upper.width || lower.height != upper.height || lower.texels.size() != upper.texels.size())
        throw std::invalid_argument("merge_slices: the slices differ in size");
    image_rgba8 out = lower;
    for (std::size_t i = 0; i < out.texels.size(); i += 4) {
        const float keep = 1.0f - float(upper.texels[i + 3]) / 255.0f;
        for (std::size_t k = 0; k < 4; ++k) {
            const float v = float(upper.texels[i + k]) + float(lower.texels[i + k]) * keep;
            out.texels[i + k] = std::uint8_t(std::min(255.0f, std::round(v)));
        }
    }
    return out;
}

namespace {

// Pairs (2k, 2k + 1) merged by `merge`, an odd top slice carried up.
template <class Merge>
std::vector<image_rgba8> pair_up(const std::vector<image_rgba8>& slices, const Merge& merge) {
    std::vector<image_rgba8> level;
    level.reserve((slices.size() + 1) / 2);
    for (std::size_t k = 0; k + 1 < slices.size(); k += 2) level.push_back(merge(slices[k], slices[k + 1]));
    if (slices.size() % 2 == 1) level.push_back(slices.back());
    return level;
}

// One texel's "upper over lower by coverage" (the normals' and the transfer's merge): weights
// α_u and α_l·(1 − α_u) from the two coverage bytes, each value their weighted mean (the upper's
// where neither is covered), the coverage merged as alpha.
struct coverage_merge {
    float upper = 0.0f, lower = 0.0f, total = 0.0f;
    coverage_merge(std::uint8_t upper_coverage, std::uint8_t lower_coverage)
        : upper(float(upper_coverage) / 255.0f),
          lower(float(lower_coverage) / 255.0f * (1.0f - upper)),
          total(upper + lower) {}
    std::uint8_t value(std::uint8_t u, std::uint8_t l) const {
        const float v = total > 0.0f ? (float(u) * upper + float(l) * lower) / total : float(u);
        return std::uint8_t(std::min(255.0f, std::round(v)));
    }
    std::uint8_t coverage() const { return std::uint8_t(std::min(255.0f, std::round(total * 255.0f))); }
};

}  // namespace

std::vector<image_rgba8> next_pyramid_level(const std::vector<image_rgba8>& slices) {
    return pair_up(slices, merge_slices);
}

image_rgba8 merge_normal_slices(const image_rgba8& lower, const image_rgba8& upper) {
    if (lower.width != upper.width || lower.height != upper.height || lower.texels.size() != upper.texels.size())
        throw std::invalid_argument("merge_normal_slices: the slices differ in size");
    image_rgba8 out = lower;
    for (std::size_t i = 0; i < out.texels.size(); i += 4) {
        const coverage_merge m(upper.texels[i + 3], lower.texels[i + 3]);
        for (std::size_t k = 0; k < 3; ++k) out.texels[i + k] = m.value(upper.texels[i + k], lower.texels[i + k]);
        out.texels[i + 3] = m.coverage();
    }
    return out;
}

image_rgba8 unpremultiply_slice(const image_rgba8& premultiplied) {
    image_rgba8 out = premultiplied;
    for (std::size_t i = 0; i < out.texels.size(); i += 4) {
        const float a = float(out.texels[i + 3]);
        for (std::size_t k = 0; k < 3; ++k)
            out.texels[i + k] =
                a > 0.0f ? std::uint8_t(std::min(255.0f, std::round(float(out.texels[i + k]) * 255.0f / a))) : 0;
    }
    return out;
}

image_rgba8 merge_slices_standard(const image_rgba8& lower, const image_rgba8& upper) {
    if (lower.width != upper.width || lower.height != upper.height || lower.texels.size() != upper.texels.size())
        throw std::invalid_argument("merge_slices_standard: the slices differ in size");
    image_rgba8 out = lower;
    const auto texel = [](const image_rgba8& image, std::size_t i) {
        return glm::vec4(image.texels[i], image.texels[i + 1], image.texels[i + 2], image.texels[i + 3]) / 255.0f;
    };
    for (std::size_t i = 0; i < out.texels.size(); i += 4) {
        const glm::vec4 merged = blend_standard(texel(upper, i), blend_standard(texel(lower, i), glm::vec4(0.0f)));
        for (std::size_t k = 0; k < 4; ++k)
            out.texels[i + k] = std::uint8_t(std::clamp(std::round(merged[int(k)] * 255.0f), 0.0f, 255.0f));
    }
    return out;
}

std::vector<image_rgba8> next_pyramid_level_standard(const std::vector<image_rgba8>& slices) {
    return pair_up(slices, merge_slices_standard);
}

std::vector<image_rgba8> next_normal_pyramid_level(const std::vector<image_rgba8>& slices) {
    return pair_up(slices, merge_normal_slices);
}

std::vector<image_rgba8> merge_transfer_slices(std::span<const image_rgba8> lower, std::span<const image_rgba8> upper) {
    if (lower.size() != k_transfer_pages || upper.size() != k_transfer_pages)
        throw std::invalid_argument("merge_transfer_slices: a slice's transfer is k_transfer_pages pages");
    for (std::size_t p = 0; p < k_transfer_pages; ++p)
        if (lower[p].width != lower[0].width || lower[p].height != lower[0].height ||
            upper[p].width != lower[0].width || upper[p].height != lower[0].height ||
            lower[p].texels.size() != upper[p].texels.size())
            throw std::invalid_argument("merge_transfer_slices: the pages differ in size");
    std::vector<image_rgba8> out(lower.begin(), lower.end());
    const std::size_t coverage_page = k_shell_transfer_coverage_channel / 4;
    const std::size_t coverage_channel = k_shell_transfer_coverage_channel % 4;
    for (std::size_t i = 0; i < out[0].texels.size(); i += 4) {
        const coverage_merge m(upper[coverage_page].texels[i + coverage_channel],
                               lower[coverage_page].texels[i + coverage_channel]);
        // The bytes encode T linearly (models/bake/transfer_pages.h), so they average as T does.
        for (std::size_t c = 0; c < k_shell_transfer_coverage_channel; ++c) {
            const std::size_t p = c / 4, k = i + c % 4;
            out[p].texels[k] = m.value(upper[p].texels[k], lower[p].texels[k]);
        }
        out[coverage_page].texels[i + coverage_channel] = m.coverage();
    }
    return out;
}

std::vector<image_rgba8> next_transfer_pyramid_level(const std::vector<image_rgba8>& slices) {
    if (slices.empty() || slices.size() % k_transfer_pages != 0)
        throw std::invalid_argument("next_transfer_pyramid_level: not whole slices of k_transfer_pages pages");
    const std::size_t count = slices.size() / k_transfer_pages;
    std::vector<image_rgba8> out;
    const std::span<const image_rgba8> all(slices);
    for (std::size_t k = 0; k < count; k += 2) {
        const auto lower = all.subspan(k * k_transfer_pages, k_transfer_pages);
        if (k + 1 == count) {
            out.insert(out.end(), lower.begin(), lower.end());  // an odd top slice carried up
            break;
        }
        const std::vector<image_rgba8> merged =
            merge_transfer_slices(lower, all.subspan((k + 1) * k_transfer_pages, k_transfer_pages));
        out.insert(out.end(), merged.begin(), merged.end());
    }
    return out;
}

}  // namespace sylva
