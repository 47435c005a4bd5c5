#include "models/bake/billboard_bake.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <stdexcept>

#include "models/bake/billboard_rasterizer.h"
#include "models/bake/implicit_illumination.h"
#include "models/image/texture_sampling.h"

namespace sylva {
namespace {

using namespace billboard_raster;

std::uint8_t to_byte(float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 255.0f))); }

// Colour and normal of one covered subsample.
struct shaded_sample {
    glm::vec3 colour{0.0f};  // 0..255
    glm::vec3 normal{0.0f};  // unit, model space
    // Luft 2007's k_a where the model's normals carry it as their length
    // (models/bake/implicit_illumination.h); 1 for plain unit normals.
    float ambient = 1.0f;
};


shaded_sample shade(const billboard_source& source, const sample& s) {
    const std::uint32_t triangle = s.triangle & k_triangle_mask;
    const mesh_data& mesh = *source.mesh;
    const std::uint32_t* index = &mesh.indices[std::size_t(triangle) * 3];
    const vertex& a = mesh.vertices[index[0]];
    const vertex& b = mesh.vertices[index[1]];
    const vertex& c = mesh.vertices[index[2]];
    const float w0 = 1.0f - s.lambda1 - s.lambda2;
    const glm::vec2 uv = a.uv * w0 + b.uv * s.lambda1 + c.uv * s.lambda2;
    glm::vec3 n = a.normal * w0 + b.normal * s.lambda1 + c.normal * s.lambda2;
    const float length = glm::length(n);
    n = length > 0.0f ? n / length : glm::vec3(0.0f);
    const bool implicit = carries_ambient(a) || carries_ambient(b) || carries_ambient(c);
    // Only alpha-tested (double-sided) surfaces are ever seen from the back: turn the normal
    // toward the viewer as the leaf shader does for !gl_FrontFacing. Luft 2007's realigned
    // normals light the crown by its shape and are not turned (shaders/shading.glsl shade_implicit).
    if ((s.triangle & k_back_facing_bit) && !implicit) n = -n;
    const bool leaf = (s.triangle & k_alpha_tested_bit) != 0;
    const float ambient = implicit ? glm::length(a.normal) * w0 + glm::length(b.normal) * s.lambda1 +
                                         glm::length(c.normal) * s.lambda2
                                   : 1.0f;
    return {bilinear_colour(leaf ? *source.leaf_texture : *source.bark_texture, uv, leaf), n, ambient};
}

glm::vec3 encode_normal(glm::vec3 n) { return (n * 0.5f + 0.5f) * 255.0f; }

void write_rgb(std::uint8_t* texel, glm::vec3 rgb) {
    texel[0] = to_byte(rgb.x);
    texel[1] = to_byte(rgb.y);
    texel[2] = to_byte(rgb.z);
}

// Adds one covered subsample's interpolated transfer to `sum` (seen side first): the front
// vector is the side the vertex normals face, so a back-facing leaf is seen on its back.
void add_transfer(const billboard_source& source, const sample& s, float* sum) {
    const radiance_transfer& t = *source.transfer;
    const std::uint32_t n = t.bands * t.bands;
    const std::uint32_t triangle = s.triangle & k_triangle_mask;
    const std::uint32_t* index = &source.mesh->indices[std::size_t(triangle) * 3];
    const float w[3] = {1.0f - s.lambda1 - s.lambda2, s.lambda1, s.lambda2};
    const bool back = (s.triangle & k_back_facing_bit) != 0;
    for (int k = 0; k < 3; ++k) {
        const float* front = &t.front[std::size_t(index[k]) * n];
        const float* other = &t.back[std::size_t(index[k]) * n];
        for (std::uint32_t i = 0; i < n; ++i) {
            sum[i] += w[k] * (back ? other[i] : front[i]);
            sum[9 + i] += w[k] * (back ? front[i] : other[i]);
        }
    }
}

void resolve(const billboard_source& source, const rasterizer& raster, const billboard_bake_settings& settings,
             billboard_image& out) {
    const std::uint32_t s = settings.supersampling;
    const auto& samples = raster.samples();
    for (std::uint32_t ty = 0; ty < settings.height; ++ty)
        for (std::uint32_t tx = 0; tx < settings.width; ++tx) {
            glm::vec3 colour{0.0f};
            glm::vec3 normal{0.0f};
            float ambient = 0.0f;
            float nearest = -std::numeric_limits<float>::infinity();
            std::uint32_t covered = 0;
            const std::size_t texel_index = std::size_t(ty) * settings.width + tx;
            float* transfer = source.transfer
                                  ? &out.transfer[texel_index * k_billboard_transfer_floats]
                                  : nullptr;
            for (std::uint32_t j = 0; j < s; ++j)
                for (std::uint32_t i = 0; i < s; ++i) {
                    const sample& smp = samples[std::size_t(ty * s + j) * raster.columns() + tx * s + i];
                    if (smp.triangle == k_no_triangle) continue;
                    const shaded_sample shaded = shade(source, smp);
                    colour += shaded.colour;
                    normal += shaded.normal;
                    ambient += shaded.ambient;
                    if (transfer) add_transfer(source, smp, transfer);
                    nearest = std::max(nearest, smp.depth);
                    ++covered;
                }
            const std::size_t texel = std::size_t(ty) * settings.width + tx;
            out.covered[texel] = std::uint16_t(covered);
            if (covered == 0) continue;
            if (transfer)
                for (std::size_t i = 0; i < k_billboard_transfer_floats; ++i)
                    transfer[i] /= float(covered);
            const float n_length = glm::length(normal);
            normal = n_length > 0.0f ? normal / n_length : raster.plane_normal();
            // The normal page carries k_a as the normal's length too (1: a plain model's, exactly).
            ambient /= float(covered);
            if (ambient != 1.0f) normal *= ambient;
            out.ambient[texel] = ambient;
            const std::uint32_t total = s * s;
            const auto alpha = std::uint8_t((covered * 255 + total / 2) / total);
            write_rgb(out.albedo.at(tx, ty), colour / float(covered));
            out.albedo.at(tx, ty)[3] = alpha;
            write_rgb(out.normal.at(tx, ty), encode_normal(normal));
            out.normal.at(tx, ty)[3] = alpha;
            out.depth[texel] = nearest;
        }
}

// Grows covered colours into uncovered texels ring by ring (each new texel the mean of its
// already filled 8-neighbours, so the nearest covered colours), then gives what is left the
// mean covered colour: bilinear filtering and mipmaps then average with plausible colours
// instead of black. Alpha stays 0.
void dilate(billboard_image& image, std::uint32_t rings, glm::vec3 fallback_normal) {
    const std::uint32_t w = image.albedo.width;
    const std::uint32_t h = image.albedo.height;
    std::vector<std::uint8_t> filled(std::size_t(w) * h);
    glm::dvec3 albedo_sum{0.0};
    glm::dvec3 normal_sum{0.0};
    std::size_t covered_texels = 0;
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x)
            if (image.covered[std::size_t(y) * w + x] > 0) {
                filled[std::size_t(y) * w + x] = 1;
                const std::uint8_t* a = image.albedo.at(x, y);
                const std::uint8_t* n = image.normal.at(x, y);
                albedo_sum += glm::dvec3(a[0], a[1], a[2]);
                normal_sum += glm::dvec3(n[0], n[1], n[2]);
                ++covered_texels;
            }
    std::vector<std::uint8_t> next = filled;
    for (std::uint32_t ring = 0; ring < rings; ++ring) {
        bool grew = false;
        for (std::uint32_t y = 0; y < h; ++y)
            for (std::uint32_t x = 0; x < w; ++x) {
                if (filled[std::size_t(y) * w + x]) continue;
                glm::vec3 albedo{0.0f};
                glm::vec3 normal{0.0f};
                int count = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const std::int64_t nx = std::int64_t(x) + dx;
                        const std::int64_t ny = std::int64_t(y) + dy;
                        if (nx < 0 || ny < 0 || nx >= std::int64_t(w) || ny >= std::int64_t(h)) continue;
                        if (!filled[std::size_t(ny) * w + std::size_t(nx)]) continue;
                        const std::uint8_t* a = image.albedo.at(std::uint32_t(nx), std::uint32_t(ny));
                        const std::uint8_t* n = image.normal.at(std::uint32_t(nx), std::uint32_t(ny));
                        albedo += glm::vec3(a[0], a[1], a[2]);
                        normal += glm::vec3(n[0], n[1], n[2]);
                        ++count;
                    }
                if (count == 0) continue;
                write_rgb(image.albedo.at(x, y), albedo / float(count));
                write_rgb(image.normal.at(x, y), normal / float(count));
                next[std::size_t(y) * w + x] = 1;
                grew = true;
            }
        filled = next;
        if (!grew) break;
    }
    const glm::vec3 rest_albedo = covered_texels ? glm::vec3(albedo_sum / double(covered_texels)) : glm::vec3(0.0f);
    const glm::vec3 rest_normal =
        covered_texels ? glm::vec3(normal_sum / double(covered_texels)) : encode_normal(fallback_normal);
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x)
            if (!filled[std::size_t(y) * w + x]) {
                write_rgb(image.albedo.at(x, y), rest_albedo);
                write_rgb(image.normal.at(x, y), rest_normal);
            }
}

// Uncovered texels take the mean covered transfer: they are discarded by the alpha test, and
// only bilinear filtering at a leaf's edge reads them.
void fill_uncovered_transfer(billboard_image& image) {
    std::array<double, k_billboard_transfer_floats> sum{};
    std::size_t covered = 0;
    for (std::size_t t = 0; t < image.covered.size(); ++t)
        if (image.covered[t]) {
            for (std::size_t i = 0; i < sum.size(); ++i)
                sum[i] += image.transfer[t * k_billboard_transfer_floats + i];
            ++covered;
        }
    if (covered == 0) return;
    for (std::size_t t = 0; t < image.covered.size(); ++t)
        if (!image.covered[t])
            for (std::size_t i = 0; i < sum.size(); ++i)
                image.transfer[t * k_billboard_transfer_floats + i] =
                    float(sum[i] / double(covered));
}

void validate(const billboard_source& source, const billboard_plane& plane, const billboard_bake_settings& settings) {
    if (!source.mesh || !source.leaf_texture || !source.bark_texture)
        throw std::invalid_argument("bake_billboard: mesh, leaf texture and bark texture are required");
    for (const image_rgba8* t : {source.leaf_texture, source.bark_texture})
        if (t->width == 0 || t->height == 0 || t->texels.size() != std::size_t(t->width) * t->height * 4)
            throw std::invalid_argument("bake_billboard: empty or malformed texture");
    if (settings.width == 0 || settings.height == 0 || settings.supersampling == 0 || settings.supersampling > 255)
        throw std::invalid_argument("bake_billboard: zero resolution, or supersampling not in 1..255");
    if (std::uint64_t(settings.width) * settings.supersampling > k_max_samples_per_side ||
        std::uint64_t(settings.height) * settings.supersampling > k_max_samples_per_side)
        throw std::invalid_argument("bake_billboard: more than 65536 subsamples per side");
    if (source.mesh->triangle_count() > k_triangle_mask)
        throw std::invalid_argument("bake_billboard: more than 2^30 triangles");
    if (source.transfer && (source.transfer->bands < 2 || source.transfer->bands > 3 ||
                            source.transfer->receiver_count() != source.mesh->vertices.size() ||
                            source.transfer->back.size() != source.transfer->front.size()))
        throw std::invalid_argument(
            "bake_billboard: the transfer must have 2 or 3 bands and one receiver per vertex");
    const float lu = glm::length(plane.axis_u);
    const float lv = glm::length(plane.axis_v);
    if (!(lu > 0.0f) || !(lv > 0.0f) || std::abs(glm::dot(plane.axis_u, plane.axis_v)) > 1e-4f * lu * lv)
        throw std::invalid_argument("bake_billboard: plane axes must be non-zero and orthogonal");
}

}  // namespace

glm::vec3 billboard_plane::normal() const { return glm::normalize(glm::cross(axis_u, axis_v)); }

billboard_plane back_side(const billboard_plane& plane) {
    return {plane.origin + plane.axis_u, -plane.axis_u, plane.axis_v};
}

billboard_image bake_billboard(const billboard_source& source, const billboard_plane& plane,
                               const billboard_bake_settings& settings) {
    validate(source, plane, settings);
    rasterizer raster(source, plane, settings);
    raster.draw_all();

    billboard_image out;
    const std::size_t texels = std::size_t(settings.width) * settings.height;
    for (image_rgba8* image : {&out.albedo, &out.normal}) {
        image->width = settings.width;
        image->height = settings.height;
        image->texels.assign(texels * 4, 0);
    }
    out.depth.assign(texels, 0.0f);
    out.covered.assign(texels, 0);
    out.ambient.assign(texels, 1.0f);
    if (source.transfer) out.transfer.assign(texels * k_billboard_transfer_floats, 0.0f);
    resolve(source, raster, settings, out);
    if (source.transfer) fill_uncovered_transfer(out);
    dilate(out, settings.dilation_texels, raster.plane_normal());
    return out;
}

}  // namespace sylva
