#include "models/bake/billboard_bake.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <stdexcept>

#include "models/bake/implicit_illumination.h"
#include "models/image/texture_sampling.h"

namespace sylva {
namespace {

// Subsample positions in fixed point with 8 fractional bits. Projected coordinates are clamped
// to ±2^28 (±2^20 subsamples, far beyond any plane's grid), so edge-function products stay
// below 2^59 and every edge test is exact integer arithmetic.
constexpr int k_subpixel_bits = 8;
constexpr std::int64_t k_subpixel_one = std::int64_t(1) << k_subpixel_bits;
constexpr double k_fixed_limit = double(std::int64_t(1) << 28);
constexpr std::uint32_t k_no_triangle = std::numeric_limits<std::uint32_t>::max();
// sample::triangle holds the triangle index in its low 30 bits and these two flags.
constexpr std::uint32_t k_back_facing_bit = 0x80000000u;
constexpr std::uint32_t k_alpha_tested_bit = 0x40000000u;
constexpr std::uint32_t k_triangle_mask = 0x3fffffffu;
constexpr std::uint32_t k_max_samples_per_side = 65536;

enum class surface : std::uint8_t { skip, opaque, alpha_tested };

surface surface_of(material_kind m) {
    switch (m) {
        case material_kind::bark:
        case material_kind::ground: return surface::opaque;
        case material_kind::leaf:
        case material_kind::billboard:
        case material_kind::facing_billboard:
        case material_kind::billboard_cloud: return surface::alpha_tested;
    }
    return surface::skip;
}

// What the nearest surface left in one subsample; resolved into texels after every triangle.
struct sample {
    float depth = -std::numeric_limits<float>::infinity();
    std::uint32_t triangle = k_no_triangle;  // index | k_back_facing_bit | k_alpha_tested_bit
    float lambda1 = 0.0f;  // barycentric weights of the triangle's 2nd and 3rd index
    float lambda2 = 0.0f;
};

struct projected_vertex {
    std::int64_t x = 0;  // fixed-point subsample column
    std::int64_t y = 0;  // fixed-point subsample row, growing downward (image rows)
    float depth = 0.0f;
};


// Is a subsample lying exactly on edge a -> b inside? Exactly one of a -> b and b -> a says yes
// (an antisymmetric choice equivalent to the top-left rule), so a shared edge is counted once.
bool owns_edge(std::int64_t dx, std::int64_t dy) { return dy < 0 || (dy == 0 && dx > 0); }

// A triangle ready to rasterize: projected, culled, wound positively, its subsample bounds known.
struct prepared_triangle {
    projected_vertex v[3];  // v[1], v[2] swapped for a front face (see setup())
    std::int64_t area = 0;
    std::int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // inclusive subsample bounds, clipped to the grid
    float nearest = 0.0f;  // the largest vertex depth
    std::uint32_t triangle = 0;
    bool front_facing = false;
    bool alpha_tested = false;
};

// Subsample i's centre is at i + 1/2: the first and last centres inside [lo, hi] (fixed point).
std::int64_t first_sample(std::int64_t lo) {
    const std::int64_t n = lo - k_subpixel_one / 2;
    return n <= 0 ? -((-n) >> k_subpixel_bits) : ((n + k_subpixel_one - 1) >> k_subpixel_bits);
}
std::int64_t last_sample(std::int64_t hi) {
    const std::int64_t n = hi - k_subpixel_one / 2;
    return n >= 0 ? (n >> k_subpixel_bits) : -((-n + k_subpixel_one - 1) >> k_subpixel_bits);
}

// Binned: triangles are sorted nearest first, then drawn tile by tile (each tile's triangles in
// that order), so the subsamples a triangle touches stay in cache. Tiles are independent, so the
// result does not depend on the tile size either.
class rasterizer {
public:
    static constexpr std::uint32_t k_tile = 64;  // subsamples per tile side

    rasterizer(const billboard_source& source, const billboard_plane& plane, const billboard_bake_settings& settings)
        : m_source(source) {
        m_columns = settings.width * settings.supersampling;
        m_rows = settings.height * settings.supersampling;
        m_samples.resize(std::size_t(m_columns) * m_rows);
        m_origin = plane.origin;
        m_normal = plane.normal();
        m_u_scale = plane.axis_u * (float(m_columns) / glm::dot(plane.axis_u, plane.axis_u));
        m_v_scale = plane.axis_v * (float(m_rows) / glm::dot(plane.axis_v, plane.axis_v));
    }

    void draw_all() {
        const std::vector<prepared_triangle> triangles = prepare();
        const std::uint32_t tiles_x = (m_columns + k_tile - 1) / k_tile;
        const std::uint32_t tiles_y = (m_rows + k_tile - 1) / k_tile;
        std::vector<std::vector<std::uint32_t>> bins(std::size_t(tiles_x) * tiles_y);
        for (std::uint32_t i = 0; i < triangles.size(); ++i) {
            const prepared_triangle& t = triangles[i];
            for (std::int64_t ty = t.y0 / k_tile; ty <= t.y1 / k_tile; ++ty)
                for (std::int64_t tx = t.x0 / k_tile; tx <= t.x1 / k_tile; ++tx)
                    bins[std::size_t(ty) * tiles_x + std::size_t(tx)].push_back(i);
        }
        for (std::uint32_t ty = 0; ty < tiles_y; ++ty)
            for (std::uint32_t tx = 0; tx < tiles_x; ++tx) draw_tile(triangles, bins[std::size_t(ty) * tiles_x + tx], tx, ty);
    }

    const std::vector<sample>& samples() const { return m_samples; }
    std::uint32_t columns() const { return m_columns; }
    glm::vec3 plane_normal() const { return m_normal; }

private:
    material_kind material_of(std::uint32_t triangle) const {
        const std::size_t first = std::size_t(triangle) * 3;
        if (first + 3 > m_source.mesh->indices.size())
            throw std::invalid_argument("bake_billboard: triangle index out of range");
        for (const submesh& sub : m_source.mesh->submeshes)
            if (first >= sub.first_index && first < std::size_t(sub.first_index) + sub.index_count)
                return sub.material;
        return static_cast<material_kind>(0xff);  // in no submesh: surface_of says skip
    }

    // Every triangle that can cover a subsample, nearest first (by its nearest vertex, then
    // index: a total order, so the result does not depend on the sort): most hidden subsamples
    // then fail the depth test before the costlier alpha test.
    std::vector<prepared_triangle> prepare() const {
        std::vector<prepared_triangle> queue;
        auto enqueue = [&](std::uint32_t t, surface kind) {
            prepared_triangle p;
            if (kind != surface::skip && setup(t, kind, p)) queue.push_back(p);
        };
        if (m_source.triangles.empty()) {
            for (const submesh& sub : m_source.mesh->submeshes)
                for (std::uint32_t t = sub.first_index / 3; t < (sub.first_index + sub.index_count) / 3; ++t)
                    enqueue(t, surface_of(sub.material));
        } else {
            for (std::uint32_t t : m_source.triangles) enqueue(t, surface_of(material_of(t)));
        }
        std::sort(queue.begin(), queue.end(), [](const prepared_triangle& a, const prepared_triangle& b) {
            return a.nearest != b.nearest ? a.nearest > b.nearest : a.triangle < b.triangle;
        });
        return queue;
    }

    // Once every subsample of the tile is covered, the farthest of them bounds what can still
    // show: a triangle entirely behind it (all its depths <= its nearest vertex, with a margin
    // for rounding) would fail every depth test and is skipped. Depths only grow, so a stale
    // bound stays conservative; it is refreshed every k_refresh triangles.
    void draw_tile(const std::vector<prepared_triangle>& triangles, const std::vector<std::uint32_t>& bin,
                   std::uint32_t tx, std::uint32_t ty) {
        constexpr std::uint32_t k_refresh = 64;
        const std::int64_t x0 = std::int64_t(tx) * k_tile;
        const std::int64_t y0 = std::int64_t(ty) * k_tile;
        const std::int64_t x1 = std::min<std::int64_t>(x0 + k_tile, m_columns) - 1;
        const std::int64_t y1 = std::min<std::int64_t>(y0 + k_tile, m_rows) - 1;
        m_uncovered = std::size_t(x1 - x0 + 1) * std::size_t(y1 - y0 + 1);
        float farthest = -std::numeric_limits<float>::infinity();
        std::uint32_t since_refresh = 0;
        for (std::uint32_t i : bin) {
            const prepared_triangle& t = triangles[i];
            if (m_uncovered == 0) {
                if (since_refresh-- == 0) {
                    farthest = farthest_depth(x0, y0, x1, y1);
                    since_refresh = k_refresh;
                }
                if (t.nearest + 1e-4f * (1.0f + std::abs(t.nearest)) < farthest) continue;
            }
            rasterize(t, std::max(x0, t.x0), std::max(y0, t.y0), std::min(x1, t.x1), std::min(y1, t.y1));
        }
    }

    float farthest_depth(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) const {
        float farthest = std::numeric_limits<float>::infinity();
        for (std::int64_t y = y0; y <= y1; ++y)
            for (std::int64_t x = x0; x <= x1; ++x)
                farthest = std::min(farthest, m_samples[std::size_t(y) * m_columns + std::size_t(x)].depth);
        return farthest;
    }

    projected_vertex project(glm::vec3 p) const {
        const glm::vec3 d = p - m_origin;
        const double column = double(glm::dot(d, m_u_scale));
        const double row = double(m_rows) - double(glm::dot(d, m_v_scale));
        auto fixed = [](double v) {
            return std::int64_t(std::llround(std::clamp(v * double(k_subpixel_one), -k_fixed_limit, k_fixed_limit)));
        };
        return {fixed(column), fixed(row), glm::dot(d, m_normal)};
    }

    // False when the triangle covers no subsample: edge-on, a culled back face, off the grid.
    bool setup(std::uint32_t triangle, surface kind, prepared_triangle& p) const {
        const mesh_data& mesh = *m_source.mesh;
        const std::uint32_t* index = &mesh.indices[std::size_t(triangle) * 3];
        for (int k = 0; k < 3; ++k) p.v[k] = project(mesh.vertices[index[k]].position);
        p.area = (p.v[1].x - p.v[0].x) * (p.v[2].y - p.v[0].y) - (p.v[1].y - p.v[0].y) * (p.v[2].x - p.v[0].x);
        if (p.area == 0) return false;
        // Rows grow downward, so a triangle counter-clockwise as the viewer sees it (GL's front
        // face) has a negative area here; it is rasterized with 2nd and 3rd vertex swapped.
        p.front_facing = p.area < 0;
        if (kind == surface::opaque && !p.front_facing) return false;  // bark is back-face culled
        if (p.front_facing) {
            std::swap(p.v[1], p.v[2]);
            p.area = -p.area;
        }
        p.x0 = std::max<std::int64_t>(first_sample(std::min({p.v[0].x, p.v[1].x, p.v[2].x})), 0);
        p.x1 = std::min<std::int64_t>(last_sample(std::max({p.v[0].x, p.v[1].x, p.v[2].x})), m_columns - 1);
        p.y0 = std::max<std::int64_t>(first_sample(std::min({p.v[0].y, p.v[1].y, p.v[2].y})), 0);
        p.y1 = std::min<std::int64_t>(last_sample(std::max({p.v[0].y, p.v[1].y, p.v[2].y})), m_rows - 1);
        p.nearest = std::max({p.v[0].depth, p.v[1].depth, p.v[2].depth});
        const float farthest = std::min({p.v[0].depth, p.v[1].depth, p.v[2].depth});
        if (p.nearest < m_source.slab_min || farthest >= m_source.slab_max) return false;  // outside the slab
        p.triangle = triangle;
        p.alpha_tested = kind == surface::alpha_tested;
        return p.x0 <= p.x1 && p.y0 <= p.y1;
    }

    void rasterize(const prepared_triangle& t, std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) {
        // Edge k runs from v[k+1] to v[k+2]; its function is the weight of v[k] times the area:
        // e_k(p) = a_k * p.x + b_k * p.y + c_k, positive inside, exact in integers. Subsamples
        // on an edge the triangle does not own get a bias of -1 and so fail `>= 0`.
        std::int64_t a[3], b[3], row_start[3];
        const std::int64_t px0 = x0 * k_subpixel_one + k_subpixel_one / 2;
        const std::int64_t py0 = y0 * k_subpixel_one + k_subpixel_one / 2;
        for (int k = 0; k < 3; ++k) {
            const projected_vertex& p = t.v[(k + 1) % 3];
            const projected_vertex& q = t.v[(k + 2) % 3];
            a[k] = -(q.y - p.y);
            b[k] = q.x - p.x;
            const std::int64_t bias = owns_edge(q.x - p.x, q.y - p.y) ? 0 : -1;
            row_start[k] = a[k] * (px0 - p.x) + b[k] * (py0 - p.y) + bias;
        }
        const double inverse_area = 1.0 / double(t.area);
        const std::int64_t step[3] = {a[0] * k_subpixel_one, a[1] * k_subpixel_one, a[2] * k_subpixel_one};
        for (std::int64_t y = y0; y <= y1; ++y) {
            // The row's span: the subsamples x0 + i with every e_k + step_k * i >= 0, solved
            // exactly in integers so only covered subsamples are visited.
            std::int64_t lo = 0;
            std::int64_t hi = x1 - x0;
            for (int k = 0; k < 3 && lo <= hi; ++k) {
                const std::int64_t e = row_start[k];
                if (step[k] > 0) {
                    if (e < 0) lo = std::max(lo, (-e + step[k] - 1) / step[k]);
                } else if (step[k] < 0) {
                    if (e < 0) lo = hi + 1;
                    else hi = std::min(hi, e / -step[k]);
                } else if (e < 0) {
                    lo = hi + 1;
                }
            }
            sample* row = &m_samples[std::size_t(y) * m_columns + std::size_t(x0)];
            std::int64_t e[3] = {row_start[0] + step[0] * lo, row_start[1] + step[1] * lo, row_start[2] + step[2] * lo};
            for (std::int64_t i = lo; i <= hi; ++i) {
                cover(row[i], t, e, inverse_area);
                for (int k = 0; k < 3; ++k) e[k] += step[k];
            }
            for (int k = 0; k < 3; ++k) row_start[k] += b[k] * k_subpixel_one;
        }
    }

    // The bias of -1 leaves weights one unit low: negligible next to areas of 2^16 per
    // subsample squared, and identical for every run.
    void cover(sample& s, const prepared_triangle& t, const std::int64_t (&e)[3], double inverse_area) {
        const double l0 = double(e[0]) * inverse_area;
        const double l1 = double(e[1]) * inverse_area;
        const double l2 = 1.0 - l0 - l1;
        const float depth =
            float(l0 * double(t.v[0].depth) + l1 * double(t.v[1].depth) + l2 * double(t.v[2].depth));
        if (!(depth > s.depth)) return;
        if (depth < m_source.slab_min || depth >= m_source.slab_max) return;
        // Weights of the triangle's own 2nd and 3rd index (v[1] and v[2] were swapped for a
        // front face).
        const float w1 = float(t.front_facing ? l2 : l1);
        const float w2 = float(t.front_facing ? l1 : l2);
        if (t.alpha_tested) {
            const mesh_data& mesh = *m_source.mesh;
            const std::uint32_t* index = &mesh.indices[std::size_t(t.triangle) * 3];
            const glm::vec2 uv = mesh.vertices[index[0]].uv * (1.0f - w1 - w2) + mesh.vertices[index[1]].uv * w1 +
                                 mesh.vertices[index[2]].uv * w2;
            if (bilinear_alpha(*m_source.leaf_texture, uv) < 127.5f) return;  // GL: discard below 0.5
        }
        m_uncovered -= s.triangle == k_no_triangle;
        s.depth = depth;
        s.triangle = t.triangle | (t.front_facing ? 0u : k_back_facing_bit) | (t.alpha_tested ? k_alpha_tested_bit : 0u);
        s.lambda1 = w1;
        s.lambda2 = w2;
    }

    const billboard_source& m_source;
    std::uint32_t m_columns = 0;
    std::uint32_t m_rows = 0;
    std::vector<sample> m_samples;
    std::size_t m_uncovered = 0;  // subsamples of the current tile nothing has covered yet
    glm::vec3 m_origin{0.0f};
    glm::vec3 m_normal{0.0f};
    glm::vec3 m_u_scale{0.0f};  // model offset -> subsample columns
    glm::vec3 m_v_scale{0.0f};  // model offset -> subsample rows counted upward
};

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
