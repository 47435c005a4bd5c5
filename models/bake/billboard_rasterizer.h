#pragma once
// The deterministic CPU orthographic rasterizer the billboard bakes draw with
// (models/bake/billboard_bake.h bake_billboard): a plant's triangles (all, or one cluster's)
// projected onto a billboard_plane's supersampled grid, with exact fixed-point edge functions and
// a top-left rule (a shared edge counted once), a depth test, then the leaf texture's alpha test;
// each subsample keeps its nearest surface's triangle and barycentric weights, which
// billboard_bake.cpp resolves into texels. Binned into tiles, nearest triangles first, so the
// result does not depend on the tile size or the sort's ties.
//
// Written by hand (see billboard_bake.h): no Debian library rasterizes into CPU arrays with a
// custom resolve. Header-only: billboard_bake.cpp is its one user, and keeping its small
// functions inline keeps the inner loop as the compiler saw it before it had its own file.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <stdexcept>
#include <vector>

#include "models/bake/billboard_bake.h"
#include "models/image/texture_sampling.h"

namespace sylva::billboard_raster {

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
        case material_kind::ground:
            return surface::opaque;
        case material_kind::leaf:
        case material_kind::billboard:
        case material_kind::facing_billboard:
        case material_kind::billboard_cloud:
            return surface::alpha_tested;
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
bool owns_edge(std::int64_t dx, std::int64_t dy) {
    return dy < 0 || (dy == 0 && dx > 0);
}

// A triangle ready to rasterize: projected, culled, wound positively, its subsample bounds known.
struct prepared_triangle {
    projected_vertex v[3];  // v[1], v[2] swapped for a front face (see setup())
    std::int64_t area = 0;
    std::int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // inclusive subsample bounds, clipped to the grid
    float nearest = 0.0f;                         // the largest vertex depth
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

    rasterizer(const billboard_source& source, const billboard_plane& plane,
               const billboard_bake_settings& settings)
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
            for (std::uint32_t tx = 0; tx < tiles_x; ++tx)
                draw_tile(triangles, bins[std::size_t(ty) * tiles_x + tx], tx, ty);
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
                for (std::uint32_t t = sub.first_index / 3;
                     t < (sub.first_index + sub.index_count) / 3; ++t)
                    enqueue(t, surface_of(sub.material));
        } else {
            for (std::uint32_t t : m_source.triangles) enqueue(t, surface_of(material_of(t)));
        }
        std::sort(
            queue.begin(), queue.end(), [](const prepared_triangle& a, const prepared_triangle& b) {
                return a.nearest != b.nearest ? a.nearest > b.nearest : a.triangle < b.triangle;
            });
        return queue;
    }

    // Once every subsample of the tile is covered, the farthest of them bounds what can still
    // show: a triangle entirely behind it (all its depths <= its nearest vertex, with a margin
    // for rounding) would fail every depth test and is skipped. Depths only grow, so a stale
    // bound stays conservative; it is refreshed every k_refresh triangles.
    void draw_tile(const std::vector<prepared_triangle>& triangles,
                   const std::vector<std::uint32_t>& bin, std::uint32_t tx, std::uint32_t ty) {
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
            rasterize(t, std::max(x0, t.x0), std::max(y0, t.y0), std::min(x1, t.x1),
                      std::min(y1, t.y1));
        }
    }

    float farthest_depth(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1) const {
        float farthest = std::numeric_limits<float>::infinity();
        for (std::int64_t y = y0; y <= y1; ++y)
            for (std::int64_t x = x0; x <= x1; ++x)
                farthest = std::min(farthest,
                                    m_samples[std::size_t(y) * m_columns + std::size_t(x)].depth);
        return farthest;
    }

    projected_vertex project(glm::vec3 p) const {
        const glm::vec3 d = p - m_origin;
        const double column = double(glm::dot(d, m_u_scale));
        const double row = double(m_rows) - double(glm::dot(d, m_v_scale));
        auto fixed = [](double v) {
            return std::int64_t(std::llround(
                std::clamp(v * double(k_subpixel_one), -k_fixed_limit, k_fixed_limit)));
        };
        return {fixed(column), fixed(row), glm::dot(d, m_normal)};
    }

    // False when the triangle covers no subsample: edge-on, a culled back face, off the grid.
    bool setup(std::uint32_t triangle, surface kind, prepared_triangle& p) const {
        const mesh_data& mesh = *m_source.mesh;
        const std::uint32_t* index = &mesh.indices[std::size_t(triangle) * 3];
        for (int k = 0; k < 3; ++k) p.v[k] = project(mesh.vertices[index[k]].position);
        p.area = (p.v[1].x - p.v[0].x) * (p.v[2].y - p.v[0].y) -
                 (p.v[1].y - p.v[0].y) * (p.v[2].x - p.v[0].x);
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
        p.x1 = std::min<std::int64_t>(last_sample(std::max({p.v[0].x, p.v[1].x, p.v[2].x})),
                                      m_columns - 1);
        p.y0 = std::max<std::int64_t>(first_sample(std::min({p.v[0].y, p.v[1].y, p.v[2].y})), 0);
        p.y1 = std::min<std::int64_t>(last_sample(std::max({p.v[0].y, p.v[1].y, p.v[2].y})),
                                      m_rows - 1);
        p.nearest = std::max({p.v[0].depth, p.v[1].depth, p.v[2].depth});
        const float farthest = std::min({p.v[0].depth, p.v[1].depth, p.v[2].depth});
        if (p.nearest < m_source.slab_min || farthest >= m_source.slab_max)
            return false;  // outside the slab
        p.triangle = triangle;
        p.alpha_tested = kind == surface::alpha_tested;
        return p.x0 <= p.x1 && p.y0 <= p.y1;
    }

    void rasterize(const prepared_triangle& t, std::int64_t x0, std::int64_t y0, std::int64_t x1,
                   std::int64_t y1) {
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
        const std::int64_t step[3] = {a[0] * k_subpixel_one, a[1] * k_subpixel_one,
                                      a[2] * k_subpixel_one};
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
                    if (e < 0)
                        lo = hi + 1;
                    else
                        hi = std::min(hi, e / -step[k]);
                } else if (e < 0) {
                    lo = hi + 1;
                }
            }
            sample* row = &m_samples[std::size_t(y) * m_columns + std::size_t(x0)];
            std::int64_t e[3] = {row_start[0] + step[0] * lo, row_start[1] + step[1] * lo,
                                 row_start[2] + step[2] * lo};
            for (std::int64_t i = lo; i <= hi; ++i) {
                cover(row[i], t, e, inverse_area);
                for (int k = 0; k < 3; ++k) e[k] += step[k];
            }
            for (int k = 0; k < 3; ++k) row_start[k] += b[k] * k_subpixel_one;
        }
    }

    // The bias of -1 leaves weights one unit low: negligible next to areas of 2^16 per
    // subsample squared, and identical for every run.
    void cover(sample& s, const prepared_triangle& t, const std::int64_t (&e)[3],
               double inverse_area) {
        const double l0 = double(e[0]) * inverse_area;
        const double l1 = double(e[1]) * inverse_area;
        const double l2 = 1.0 - l0 - l1;
        const float depth = float(l0 * double(t.v[0].depth) + l1 * double(t.v[1].depth) +
                                  l2 * double(t.v[2].depth));
        if (!(depth > s.depth)) return;
        if (depth < m_source.slab_min || depth >= m_source.slab_max) return;
        // Weights of the triangle's own 2nd and 3rd index (v[1] and v[2] were swapped for a
        // front face).
        const float w1 = float(t.front_facing ? l2 : l1);
        const float w2 = float(t.front_facing ? l1 : l2);
        if (t.alpha_tested) {
            const mesh_data& mesh = *m_source.mesh;
            const std::uint32_t* index = &mesh.indices[std::size_t(t.triangle) * 3];
            const glm::vec2 uv = mesh.vertices[index[0]].uv * (1.0f - w1 - w2) +
                                 mesh.vertices[index[1]].uv * w1 + mesh.vertices[index[2]].uv * w2;
            if (bilinear_alpha(*m_source.leaf_texture, uv) < 127.5f)
                return;  // GL: discard below 0.5
        }
        m_uncovered -= s.triangle == k_no_triangle;
        s.depth = depth;
        s.triangle = t.triangle | (t.front_facing ? 0u : k_back_facing_bit) |
                     (t.alpha_tested ? k_alpha_tested_bit : 0u);
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

}  // namespace sylva::billboard_raster
