#include "models/bake/shell_bake.h"

#include <algorithm>
#include <cmath>
#include <glm/vec4.hpp>
#include <limits>
#include <stdexcept>

#include "lighting/transfer_rotation.h"
#include "models/bake/billboard_bake.h"
#include "models/bake/transfer_pages.h"

namespace sylva {
namespace {

// A slab's premultiplied colour and normal as floats, with the height of its highest surface,
// for compositing species and blurring before the 8-bit store.
struct slab_layer {
    std::uint32_t side = 0;
    std::vector<glm::vec4> colour;  // premultiplied
    std::vector<glm::vec4> normal;  // rgb n·0.5 + 0.5 of the highest surface, a coverage
    std::vector<float> top;         // the highest surface's height, −inf where none
    // With transfer: the highest surface's (k_billboard_transfer_floats a texel) and its Luft
    // 2007 k_a (1 for a plain model), else empty.
    std::vector<float> transfer;
    std::vector<float> ambient;
};

slab_layer empty_layer(std::uint32_t side, bool transfer) {
    slab_layer l;
    l.side = side;
    const std::size_t n = std::size_t(side) * side;
    l.colour.assign(n, glm::vec4(0.0f));
    l.normal.assign(n, glm::vec4(0.0f));
    l.top.assign(n, -std::numeric_limits<float>::infinity());
    if (transfer) {
        l.transfer.assign(n * k_billboard_transfer_floats, 0.0f);
        l.ambient.assign(n, 1.0f);
    }
    return l;
}

// `image` (one species' slab) composited with what the layer holds: the higher surface over the
// lower, c_high + c_low·(1 − α_high).
void composite(slab_layer& layer, const billboard_image& image) {
    for (std::size_t i = 0; i < layer.colour.size(); ++i) {
        if (image.covered[i] == 0) continue;
        const std::uint8_t* a = &image.albedo.texels[i * 4];
        const float alpha = float(a[3]) / 255.0f;
        const glm::vec4 c{float(a[0]) / 255.0f * alpha, float(a[1]) / 255.0f * alpha, float(a[2]) / 255.0f * alpha,
                          alpha};
        const std::uint8_t* n = &image.normal.texels[i * 4];
        const glm::vec4 normal{float(n[0]) / 255.0f, float(n[1]) / 255.0f, float(n[2]) / 255.0f, alpha};
        if (image.depth[i] >= layer.top[i]) {
            layer.colour[i] = c + layer.colour[i] * (1.0f - c.a);
            layer.normal[i] = {glm::vec3(normal), std::min(1.0f, normal.a + layer.normal[i].a * (1.0f - normal.a))};
            layer.top[i] = image.depth[i];
            if (!layer.transfer.empty()) {
                std::copy_n(&image.transfer[i * k_billboard_transfer_floats], k_billboard_transfer_floats,
                            &layer.transfer[i * k_billboard_transfer_floats]);
                layer.ambient[i] = image.ambient[i];
            }
        } else {
            layer.colour[i] = layer.colour[i] + c * (1.0f - layer.colour[i].a);
            layer.normal[i].a = std::min(1.0f, layer.normal[i].a + normal.a * (1.0f - layer.normal[i].a));
        }
    }
}

// A separable Gaussian of σ `sigma` texels over premultiplied values (so colour spreads with its
// coverage), clamped at the image's edges (the margin keeps those away from the tile).
void blur(std::vector<glm::vec4>& values, std::uint32_t side, float sigma) {
    if (!(sigma > 0.0f)) return;
    const int radius = int(std::ceil(3.0f * sigma));
    std::vector<float> weights(std::size_t(2 * radius + 1));
    float total = 0.0f;
    for (int k = -radius; k <= radius; ++k) total += weights[std::size_t(k + radius)] = std::exp(-0.5f * float(k * k) / (sigma * sigma));
    for (float& w : weights) w /= total;
    std::vector<glm::vec4> pass(values.size());
    const int last = int(side) - 1;
    for (int pass_index = 0; pass_index < 2; ++pass_index) {
        const std::vector<glm::vec4>& from = pass_index == 0 ? values : pass;
        std::vector<glm::vec4>& to = pass_index == 0 ? pass : values;
        for (int y = 0; y <= last; ++y)
            for (int x = 0; x <= last; ++x) {
                glm::vec4 sum(0.0f);
                for (int k = -radius; k <= radius; ++k) {
                    const int xx = pass_index == 0 ? std::clamp(x + k, 0, last) : x;
                    const int yy = pass_index == 0 ? y : std::clamp(y + k, 0, last);
                    sum += weights[std::size_t(k + radius)] * from[std::size_t(yy) * side + std::size_t(xx)];
                }
                to[std::size_t(y) * side + std::size_t(x)] = sum;
            }
    }
}

std::uint8_t to_byte(float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// The tile's texels x texels out of the layer's (side = texels + 2·margin).
void crop(const std::vector<glm::vec4>& values, std::uint32_t side, std::uint32_t margin, std::uint32_t texels,
          image_rgba8& out) {
    out.width = out.height = texels;
    out.texels.assign(std::size_t(texels) * texels * 4, 0);
    for (std::uint32_t y = 0; y < texels; ++y)
        for (std::uint32_t x = 0; x < texels; ++x) {
            const glm::vec4& v = values[std::size_t(y + margin) * side + (x + margin)];
            std::uint8_t* t = out.at(x, y);
            for (int k = 0; k < 4; ++k) t[k] = to_byte(v[k]);
        }
}

// The slab's transfer at transfer_texels² (models/bake/shell_bake.h shell_stack::transfer): each
// coarse texel the coverage-weighted mean of the tile texels it boxes (x in
// [⌊j·T/C⌋, ⌊(j + 1)·T/C⌋)), likewise Luft 2007's k_a, its coverage their mean. No Gaussian: the box is already wider than
// the colour's. A texel nothing covers takes the slab's mean covered transfer, so bilinear
// filtering at a crown's edge does not pull in zero light; it is never seen by itself (the
// colour's alpha is 0 there).
void downsample_transfer(const slab_layer& layer, std::uint32_t margin, std::uint32_t texels, std::uint32_t coarse,
                         std::vector<image_rgba8>& out) {
    constexpr std::size_t n = k_billboard_transfer_floats;
    std::vector<double> sums(std::size_t(coarse) * coarse * n, 0.0);
    std::vector<double> weights(std::size_t(coarse) * coarse, 0.0);
    std::vector<std::uint32_t> counts(std::size_t(coarse) * coarse, 0);
    std::vector<double> mean(n, 0.0);
    std::vector<double> ambient(std::size_t(coarse) * coarse, 0.0);
    double mean_ambient = 0.0;
    double mean_weight = 0.0;
    for (std::uint32_t y = 0; y < texels; ++y)
        for (std::uint32_t x = 0; x < texels; ++x) {
            const std::size_t coarse_index =
                std::size_t(std::uint64_t(y) * coarse / texels) * coarse + std::uint64_t(x) * coarse / texels;
            const std::size_t fine = std::size_t(y + margin) * layer.side + (x + margin);
            const double w = layer.normal[fine].a;
            ++counts[coarse_index];
            if (!(w > 0.0)) continue;
            weights[coarse_index] += w;
            mean_weight += w;
            ambient[coarse_index] += w * layer.ambient[fine];
            mean_ambient += w * layer.ambient[fine];
            for (std::size_t i = 0; i < n; ++i) {
                const double t = layer.transfer[fine * n + i];
                sums[coarse_index * n + i] += w * t;
                mean[i] += w * t;
            }
        }
    std::vector<image_rgba8> pages = blank_transfer_pages(coarse, coarse);
    for (std::uint32_t y = 0; y < coarse; ++y)
        for (std::uint32_t x = 0; x < coarse; ++x) {
            const std::size_t c = std::size_t(y) * coarse + x;
            for (std::size_t i = 0; i < n; ++i) {
                const double t = weights[c] > 0.0 ? sums[c * n + i] / weights[c]
                                 : mean_weight > 0.0 ? mean[i] / mean_weight
                                                     : 0.0;
                pages[i / 4].at(x, y)[i % 4] = encode_transfer(float(t));
            }
            pages[k_shell_transfer_coverage_channel / 4].at(x, y)[k_shell_transfer_coverage_channel % 4] =
                to_byte(float(weights[c] / double(counts[c])));
            const double k_a = weights[c] > 0.0 ? ambient[c] / weights[c] : mean_weight > 0.0 ? mean_ambient / mean_weight : 1.0;
            pages[k_shell_transfer_ambient_channel / 4].at(x, y)[k_shell_transfer_ambient_channel % 4] = to_byte(float(k_a));
        }
    out.insert(out.end(), pages.begin(), pages.end());
}

// The placed meshes' transfer in the rasterizer's form (floats, both sides per vertex).
radiance_transfer unpacked_transfer(const mesh_data& placed) {
    radiance_transfer out;
    out.bands = 3;
    out.front.reserve(placed.transfer.size() * 9);
    out.back.reserve(placed.transfer.size() * 9);
    for (const vertex_transfer& t : placed.transfer) {
        const sh9 front = transfer_side(t, 0);
        const sh9 back = transfer_side(t, 1);
        out.front.insert(out.front.end(), front.begin(), front.end());
        out.back.insert(out.back.end(), back.begin(), back.end());
    }
    return out;
}

void validate(std::span<const shell_species> species, std::span<const shell_plant> plants, double tile_size_m,
              const shell_bake_settings& settings) {
    if (!(tile_size_m > 0.0)) throw std::invalid_argument("bake_shell_stack: the tile size must be positive");
    if (settings.texels == 0 || settings.texels > 4096 || settings.slices == 0 || settings.slices > 256 ||
        settings.supersampling == 0 || settings.supersampling > 8 || !(settings.height_m >= 0.0f) ||
        !(settings.blur_texels >= 0.0f) || settings.margin_texels > 64 || settings.transfer_texels > settings.texels)
        throw std::invalid_argument(
            "bake_shell_stack: texels 1..4096, slices 1..256, supersampling 1..8, margin 0..64, height and blur >= 0, "
            "transfer texels 0..texels");
    for (const shell_species& s : species) {
        if (!s.mesh || !s.leaf_texture || !s.bark_texture)
            throw std::invalid_argument("bake_shell_stack: a species without its mesh or textures");
        if (settings.transfer_texels > 0 && s.mesh->transfer.size() != s.mesh->vertices.size())
            throw std::invalid_argument("bake_shell_stack: transfer asked for, and a species' mesh has none");
    }
    for (const shell_plant& p : plants)
        if (p.species >= species.size()) throw std::invalid_argument("bake_shell_stack: a plant's species is out of range");
}

}  // namespace

void append_placed(mesh_data& into, const mesh_data& model, const placement& where) {
    const float c = std::cos(where.yaw);
    const float s = std::sin(where.yaw);
    const auto turn = [c, s](glm::vec3 v) { return glm::vec3(c * v.x + s * v.z, v.y, -s * v.x + c * v.z); };
    const auto base = std::uint32_t(into.vertices.size());
    const glm::vec3 at{float(where.xz.x), 0.0f, float(where.xz.y)};
    for (const vertex& v : model.vertices)
        into.vertices.push_back({turn(v.position * where.scale) + at, turn(v.normal), v.uv});
    // A uniform scale leaves the transfer as it is (visibility and cosines do not change).
    for (const vertex_transfer& t : model.transfer) into.transfer.push_back(rotate_about_y(t, where.yaw));
    // Submeshes keep their material; each model's are appended in its order.
    for (const submesh& sub : model.submeshes) {
        submesh placed = sub;
        placed.first_index = std::uint32_t(into.indices.size());
        for (std::uint32_t i = 0; i < sub.index_count; ++i)
            into.indices.push_back(base + model.indices[sub.first_index + i]);
        into.submeshes.push_back(placed);
    }
}

shell_stack bake_shell_stack(std::span<const shell_species> species, std::span<const shell_plant> plants,
                             double tile_size_m, const shell_bake_settings& settings) {
    validate(species, plants, tile_size_m, settings);
    // Every species' plants as one mesh each (the rasterizer takes one leaf texture).
    std::vector<mesh_data> placed(species.size());
    for (const shell_plant& p : plants) append_placed(placed[p.species], *species[p.species].mesh, p.where);
    const bool with_transfer = settings.transfer_texels > 0;
    std::vector<radiance_transfer> transfer(with_transfer ? placed.size() : 0);
    for (std::size_t s = 0; s < transfer.size(); ++s) transfer[s] = unpacked_transfer(placed[s]);
    float top = 0.0f;
    for (const mesh_data& m : placed)
        for (const vertex& v : m.vertices) top = std::max(top, v.position.y);
    shell_stack out;
    out.tile_size_m = tile_size_m;
    const float height = settings.height_m > 0.0f ? settings.height_m : std::max(top, 1e-3f);
    out.slice_height_m = height / float(settings.slices);
    const std::uint32_t side = settings.texels + 2 * settings.margin_texels;
    const float texel_m = float(tile_size_m) / float(settings.texels);
    const float margin_m = texel_m * float(settings.margin_texels);
    const float extent = float(tile_size_m) + 2.0f * margin_m;
    // Looking down: axis_u along +x, axis_v along −z, so the normal is +y and image row 0 is at
    // z = −margin (models/bake/billboard_bake.h billboard_plane).
    billboard_plane plane;
    plane.origin = {-margin_m, 0.0f, float(tile_size_m) + margin_m};
    plane.axis_u = {extent, 0.0f, 0.0f};
    plane.axis_v = {0.0f, 0.0f, -extent};
    billboard_bake_settings bake;
    bake.width = bake.height = side;
    bake.supersampling = settings.supersampling;
    bake.dilation_texels = 0;
    for (std::uint32_t k = 0; k < settings.slices; ++k) {
        slab_layer layer = empty_layer(side, with_transfer);
        for (std::size_t s = 0; s < species.size(); ++s) {
            if (placed[s].indices.empty()) continue;
            billboard_source source;
            source.mesh = &placed[s];
            source.leaf_texture = species[s].leaf_texture;
            source.bark_texture = species[s].bark_texture;
            if (with_transfer) source.transfer = &transfer[s];
            source.slab_min = float(k) * out.slice_height_m;
            // The top slab keeps everything above it too (a plant taller than height_m).
            source.slab_max = k + 1 == settings.slices ? std::numeric_limits<float>::infinity()
                                                       : float(k + 1) * out.slice_height_m;
            composite(layer, bake_billboard(source, plane, bake));
        }
        if (with_transfer) downsample_transfer(layer, settings.margin_texels, settings.texels, settings.transfer_texels,
                                               out.transfer);
        blur(layer.colour, side, settings.blur_texels);
        // Normals are blurred weighted by their coverage, then made straight again (up where
        // nothing is covered), so uncovered texels do not pull them toward zero.
        for (glm::vec4& n : layer.normal) n = glm::vec4(glm::vec3(n) * n.a, n.a);
        blur(layer.normal, side, settings.blur_texels);
        for (glm::vec4& n : layer.normal)
            n = n.a > 0.0f ? glm::vec4(glm::vec3(n) / n.a, n.a) : glm::vec4(0.5f, 1.0f, 0.5f, 0.0f);
        out.colour.emplace_back();
        out.normal.emplace_back();
        crop(layer.colour, side, settings.margin_texels, settings.texels, out.colour.back());
        crop(layer.normal, side, settings.margin_texels, settings.texels, out.normal.back());
    }
    return out;
}

}  // namespace sylva
