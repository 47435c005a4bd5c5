#pragma once
// Hand-made plants and independent checks shared by the point and line bake tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "models/plant_model.h"
#include "models/bake/point_line_model.h"

namespace sylva::testing {

inline image_rgba8 solid_texture(std::uint8_t r, std::uint8_t g, std::uint8_t b,
                                 std::uint8_t a = 255) {
    image_rgba8 image;
    image.width = 4;
    image.height = 4;
    for (int i = 0; i < 16; ++i) image.texels.insert(image.texels.end(), {r, g, b, a});
    return image;
}

// Green, opaque where (x / block + y / block) is even, transparent elsewhere.
inline image_rgba8 checker_texture(std::uint32_t size, std::uint32_t block) {
    image_rgba8 image;
    image.width = image.height = size;
    for (std::uint32_t y = 0; y < size; ++y)
        for (std::uint32_t x = 0; x < size; ++x) {
            const bool opaque = (x / block + y / block) % 2 == 0;
            image.texels.insert(image.texels.end(), {30, 120, 20, std::uint8_t(opaque ? 255 : 0)});
        }
    return image;
}

// Bilinear alpha with GL_REPEAT, texel row 0 at v = 0, written out again here so the test does
// not trust the bake's own sampler.
inline float reference_alpha(const image_rgba8& image, glm::vec2 uv) {
    const double x = double(uv.x) * image.width - 0.5;
    const double y = double(uv.y) * image.height - 0.5;
    const double fx = std::floor(x);
    const double fy = std::floor(y);
    auto texel = [&](double tx, double ty) {
        const auto w = std::int64_t(image.width);
        const auto h = std::int64_t(image.height);
        const std::int64_t ix = ((std::int64_t(tx) % w) + w) % w;
        const std::int64_t iy = ((std::int64_t(ty) % h) + h) % h;
        return double(image.texels[std::size_t((iy * w + ix) * 4 + 3)]) / 255.0;
    };
    const double ax = x - fx;
    const double ay = y - fy;
    return float((1 - ax) * (1 - ay) * texel(fx, fy) + ax * (1 - ay) * texel(fx + 1, fy) +
                 (1 - ax) * ay * texel(fx, fy + 1) + ax * ay * texel(fx + 1, fy + 1));
}

// A quad origin, origin + u, origin + u + v, origin + v as two triangles, uvs spanning
// uv_min..uv_max; one triangle record per triangle when `part` is given.
inline void add_quad(mesh_data& mesh, glm::vec3 origin, glm::vec3 u, glm::vec3 v,
                     glm::vec2 uv_min = {0.0f, 0.0f}, glm::vec2 uv_max = {1.0f, 1.0f},
                     const triangle_part* part = nullptr) {
    const auto base = std::uint32_t(mesh.vertices.size());
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    mesh.vertices.push_back({origin, n, uv_min});
    mesh.vertices.push_back({origin + u, n, {uv_max.x, uv_min.y}});
    mesh.vertices.push_back({origin + u + v, n, uv_max});
    mesh.vertices.push_back({origin + v, n, {uv_min.x, uv_max.y}});
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    if (part != nullptr) mesh.parts.insert(mesh.parts.end(), 2, *part);
}

inline void add_triangle(mesh_data& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c,
                         const triangle_part* part = nullptr) {
    const auto base = std::uint32_t(mesh.vertices.size());
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    mesh.vertices.push_back({a, n, {0.0f, 0.0f}});
    mesh.vertices.push_back({b, n, {1.0f, 0.0f}});
    mesh.vertices.push_back({c, n, {0.0f, 1.0f}});
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
    if (part != nullptr) mesh.parts.push_back(*part);
}

// One submesh over every index from `first_index` on.
inline void close_submesh(mesh_data& mesh, std::uint32_t first_index, material_kind material) {
    mesh.submeshes.push_back(
        {first_index, std::uint32_t(mesh.indices.size()) - first_index, material});
}

inline plant_model model_of(mesh_data mesh, image_rgba8 leaf = solid_texture(40, 140, 30),
                            image_rgba8 bark = solid_texture(120, 90, 60)) {
    plant_model model;
    model.name = "hand-made";
    model.lods[0] = std::move(mesh);
    model.leaf_texture = std::move(leaf);
    model.bark_texture = std::move(bark);
    model.has_hierarchy = !model.lods[0].parts.empty();
    return model;
}

using triangle_key = std::array<std::uint32_t, 3>;

// The triangles of [first_index, first_index + 3 * count), each as its index triple.
inline std::vector<triangle_key> triangle_keys(const std::vector<std::uint32_t>& indices,
                                               std::uint32_t first_index, std::uint32_t count) {
    std::vector<triangle_key> keys;
    for (std::uint32_t t = 0; t < count; ++t) {
        const std::size_t i = first_index + 3 * std::size_t(t);
        keys.push_back({indices[i], indices[i + 1], indices[i + 2]});
    }
    return keys;
}

inline std::vector<triangle_key> sorted(std::vector<triangle_key> keys) {
    std::sort(keys.begin(), keys.end());
    return keys;
}

// Barycentric weights of p in triangle a, b, c (least squares in the triangle's plane) and the
// distance of p from that plane.
struct barycentric_fit {
    glm::vec3 weights;
    float plane_distance;
};
inline barycentric_fit fit_barycentric(glm::vec3 p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::dvec3 e1 = glm::dvec3(b - a);
    const glm::dvec3 e2 = glm::dvec3(c - a);
    const glm::dvec3 d = glm::dvec3(p - a);
    const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const double dp1 = glm::dot(d, e1), dp2 = glm::dot(d, e2);
    const double det = d11 * d22 - d12 * d12;
    const double w1 = (d22 * dp1 - d12 * dp2) / det;
    const double w2 = (d11 * dp2 - d12 * dp1) / det;
    const glm::dvec3 q = glm::dvec3(a) + w1 * e1 + w2 * e2;
    return {glm::vec3(float(1.0 - w1 - w2), float(w1), float(w2)),
            float(glm::length(glm::dvec3(p) - q))};
}

// The points of triangle t of a point part: [after[t + 1], after[t]) of the part's points.
inline std::pair<std::uint32_t, std::uint32_t> points_of(const point_line_model& m,
                                                         const lod_part& p, std::uint32_t t) {
    return {p.first_point + m.points_after[p.first_after + t + 1],
            p.first_point + m.points_after[p.first_after + t]};
}

}  // namespace sylva::testing
