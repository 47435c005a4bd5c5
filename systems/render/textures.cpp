#include "systems/render/textures.h"

#include <algorithm>
#include <array>
#include <bit>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace sylva::render {

namespace {

// The next level's size, and for each of its texels `resolve(block, out)` with the four source
// texels it covers (edges clamped, so odd sizes repeat their last row or column).
template <typename Resolve>
image_rgba8 reduce_2x2(const image_rgba8& image, Resolve resolve) {
    image_rgba8 out;
    out.width = std::max(1u, image.width / 2);
    out.height = std::max(1u, image.height / 2);
    out.texels.resize(std::size_t(out.width) * out.height * 4);
    for (std::uint32_t y = 0; y < out.height; ++y)
        for (std::uint32_t x = 0; x < out.width; ++x) {
            std::array<const std::uint8_t*, 4> block;
            for (std::uint32_t k = 0; k < 4; ++k)
                block[k] = image.at(std::min(2 * x + (k & 1), image.width - 1),
                                    std::min(2 * y + (k >> 1), image.height - 1));
            resolve(block, out.at(x, y));
        }
    return out;
}

}  // namespace

image_rgba8 downsample(const image_rgba8& image) {
    return reduce_2x2(image, [](const std::array<const std::uint8_t*, 4>& block, std::uint8_t* o) {
        for (int c = 0; c < 4; ++c) {
            unsigned sum = 0;
            for (const std::uint8_t* t : block) sum += t[c];
            o[c] = std::uint8_t((sum + 2) / 4);
        }
    });
}

image_rgba8 downsample_cut_out(const image_rgba8& image) {
    return reduce_2x2(image, [](const std::array<const std::uint8_t*, 4>& block, std::uint8_t* o) {
        unsigned weighted[3] = {0, 0, 0}, plain[3] = {0, 0, 0}, alpha = 0;
        for (const std::uint8_t* t : block) {
            for (int c = 0; c < 3; ++c) {
                weighted[c] += unsigned(t[c]) * t[3];
                plain[c] += t[c];
            }
            alpha += t[3];
        }
        for (int c = 0; c < 3; ++c)
            o[c] = std::uint8_t(alpha > 0 ? (weighted[c] + alpha / 2) / alpha : (plain[c] + 2) / 4);
        o[3] = std::uint8_t((alpha + 2) / 4);
    });
}

void bleed_colour(image_rgba8& image) {
    // Push: alpha-weighted levels down to 1x1. Pull: from the coarsest level up, every fully
    // transparent texel takes the colour of the texel covering it one level coarser (already
    // filled), so level 0 ends with the nearest opaque colours spread into every hole.
    std::vector<image_rgba8> levels{image};
    while (levels.back().width > 1 || levels.back().height > 1) levels.push_back(downsample_cut_out(levels.back()));
    for (std::size_t l = levels.size() - 1; l-- > 0;) {
        image_rgba8& fine = levels[l];
        const image_rgba8& coarse = levels[l + 1];
        for (std::uint32_t y = 0; y < fine.height; ++y)
            for (std::uint32_t x = 0; x < fine.width; ++x) {
                std::uint8_t* t = fine.at(x, y);
                if (t[3] != 0) continue;
                const std::uint8_t* parent = coarse.at(std::min(x / 2, coarse.width - 1), std::min(y / 2, coarse.height - 1));
                std::copy(parent, parent + 3, t);
            }
    }
    image = std::move(levels[0]);
}

float alpha_coverage(const image_rgba8& image, float scale) {
    std::size_t passing = 0;
    const std::size_t texels = std::size_t(image.width) * image.height;
    for (std::size_t i = 0; i < texels; ++i)
        passing += float(image.texels[i * 4 + 3]) * scale >= 127.5f ? 1 : 0;
    return texels ? float(passing) / float(texels) : 0.0f;
}

namespace {

// Fraction of the texels of columns [first, last) whose alpha passes the test.
float column_coverage(const image_rgba8& image, std::uint32_t first, std::uint32_t last) {
    std::size_t passing = 0;
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = first; x < last; ++x) passing += image.at(x, y)[3] >= 128 ? 1 : 0;
    const std::size_t texels = std::size_t(last - first) * image.height;
    return texels ? float(passing) / float(texels) : 0.0f;
}

}  // namespace

void preserve_alpha_coverage(image_rgba8& level, float target) {
    float low = 0.0f, high = 4.0f;
    for (int i = 0; i < 12; ++i) {  // coverage grows with the scale
        const float mid = 0.5f * (low + high);
        (alpha_coverage(level, mid) < target ? low : high) = mid;
    }
    const float scale = high;
    for (std::size_t i = 3; i < level.texels.size(); i += 4)
        level.texels[i] = std::uint8_t(std::min(255.0f, float(level.texels[i]) * scale + 0.5f));
}

void preserve_alpha_coverage(image_rgba8& level, float target, std::uint32_t first,
                             std::uint32_t last) {
    if (first == 0 && last == level.width) return preserve_alpha_coverage(level, target);
    image_rgba8 part{last - first, level.height,
                     std::vector<std::uint8_t>(std::size_t(last - first) * level.height * 4)};
    for (std::uint32_t y = 0; y < level.height; ++y)
        std::copy_n(level.at(first, y), std::size_t(last - first) * 4, part.at(0, y));
    preserve_alpha_coverage(part, target);
    for (std::uint32_t y = 0; y < level.height; ++y)
        std::copy_n(part.at(0, y), std::size_t(last - first) * 4, level.at(first, y));
}

gl_texture make_texture_array(std::span<const image_rgba8> layers, bool repeat, bool alpha_tested,
                              std::span<const std::uint32_t> columns) {
    if (layers.empty()) throw std::invalid_argument("make_texture_array: no layers");
    const auto w = layers[0].width;
    const auto h = layers[0].height;
    for (const auto& layer : layers)
        if (layer.width != w || layer.height != h)
            throw std::invalid_argument("make_texture_array: layers differ in size");
    gl_texture texture = make_texture(GL_TEXTURE_2D_ARRAY);
    const int levels = std::bit_width(std::max(w, h));
    glTextureStorage3D(texture.id(), levels, GL_RGBA8, GLsizei(w), GLsizei(h), GLsizei(layers.size()));
    for (std::size_t i = 0; i < layers.size(); ++i) {
        if (!alpha_tested) {
            glTextureSubImage3D(texture.id(), 0, 0, 0, GLint(i), GLsizei(w), GLsizei(h), 1, GL_RGBA,
                                GL_UNSIGNED_BYTE, layers[i].texels.data());
            continue;
        }
        // Mips built here, each from the previous one: colour averaged over the opaque texels
        // only, alpha-test coverage kept. Level 0 itself goes up with its holes' colour bled
        // in, so bilinear taps at a leaf's outline do not mix in the cut-out's colour.
        // Each image of an atlas keeps its own coverage while every image is at least a texel
        // wide; below that, the layer's.
        std::vector<std::uint32_t> edges{0, w};
        if (!columns.empty()) edges.assign(columns.begin(), columns.end());
        if (edges.size() < 2 || edges.front() != 0 || edges.back() != w ||
            !std::is_sorted(edges.begin(), edges.end()))
            throw std::invalid_argument("make_texture_array: " + std::to_string(edges.size()) +
                                        " column edges from " + std::to_string(edges.front()) + " to " +
                                        std::to_string(edges.back()) + " for layers " +
                                        std::to_string(w) + " wide (they must rise from 0 to it)");
        const float whole = alpha_coverage(layers[i]);
        std::vector<float> coverage(edges.size() - 1, 0.0f);
        for (std::size_t k = 0; k + 1 < edges.size(); ++k)
            if (edges[k + 1] > edges[k])
                coverage[k] = column_coverage(layers[i], edges[k], edges[k + 1]);
        image_rgba8 level = layers[i];
        bleed_colour(level);
        glTextureSubImage3D(texture.id(), 0, 0, 0, GLint(i), GLsizei(w), GLsizei(h), 1, GL_RGBA,
                            GL_UNSIGNED_BYTE, level.texels.data());
        for (int l = 1; l < levels; ++l) {
            level = downsample_cut_out(level);
            image_rgba8 kept = level;
            bool apart = true;
            for (std::size_t k = 0; k + 1 < edges.size(); ++k)
                apart = apart && (coverage[k] == 0.0f || (edges[k + 1] >> l) > (edges[k] >> l));
            if (!apart) {
                preserve_alpha_coverage(kept, whole);
            } else {
                for (std::size_t k = 0; k + 1 < edges.size(); ++k)
                    if (coverage[k] > 0.0f)
                        preserve_alpha_coverage(kept, coverage[k], edges[k] >> l,
                                                edges[k + 1] >> l);
            }
            glTextureSubImage3D(texture.id(), l, 0, 0, GLint(i), GLsizei(kept.width), GLsizei(kept.height),
                                1, GL_RGBA, GL_UNSIGNED_BYTE, kept.texels.data());
        }
    }
    if (!alpha_tested) glGenerateTextureMipmap(texture.id());
    const GLint wrap = repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, wrap);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, wrap);
    // Trilinear, no anisotropic filtering: on llvmpipe (Mesa 22.3) anisotropic sampling made
    // shading several times slower and caused sporadic 2-54 s frames, and the coverage-
    // preserving mips already keep distant foliage from thinning out.
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return texture;
}

gl_texture make_float_texture(int width, int height, const float* rgb) {
    gl_texture texture = make_texture(GL_TEXTURE_2D);
    // 32-bit floats: half floats overflow to infinity above 65504, which the sky reaches at the
    // scenario format's brightest settings (the stress suite renders them), and tone mapping
    // infinity gives NaN, drawn black.
    glTextureStorage2D(texture.id(), 1, GL_RGB32F, width, height);
    glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, GL_RGB, GL_FLOAT, rgb);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return texture;
}

}  // namespace sylva::render
