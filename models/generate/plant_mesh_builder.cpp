#include "models/generate/plant_mesh_builder.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace sylva {
namespace {

constexpr float k_pi = 3.14159265358979f;

void set_bounds(mesh_data& mesh) {
    if (mesh.vertices.empty()) return;
    mesh.bounds_min = mesh.bounds_max = mesh.vertices.front().position;
    for (const vertex& v : mesh.vertices) {
        mesh.bounds_min = glm::min(mesh.bounds_min, v.position);
        mesh.bounds_max = glm::max(mesh.bounds_max, v.position);
    }
}

}  // namespace

void add_tube(plant_mesh_builder& out, std::span<const tube_ring> rings, int sides, float v_scale,
              const triangle_part& part) {
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    const auto ring_size = static_cast<std::uint32_t>(sides + 1);
    float along = 0.0f;
    for (std::size_t k = 0; k < rings.size(); ++k) {
        const tube_ring& r = rings[k];
        if (k > 0) along += glm::length(r.position - rings[k - 1].position);
        const glm::vec3 binormal = glm::cross(r.tangent, r.normal);
        for (int j = 0; j <= sides; ++j) {
            const float u = static_cast<float>(j) / static_cast<float>(sides);
            const float angle = 2.0f * k_pi * u;
            const glm::vec3 radial = r.normal * std::cos(angle) + binormal * std::sin(angle);
            out.vertices.push_back({r.position + radial * r.radius, radial, {u, along / v_scale}});
        }
    }
    for (std::uint32_t k = 0; k + 1 < rings.size(); ++k) {
        for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(sides); ++j) {
            const std::uint32_t a = base + k * ring_size + j;
            const std::uint32_t b = a + ring_size;
            // Counter-clockwise seen from outside: around the ring, then along the stem.
            out.add_triangle(a, a + 1, b, part);
            out.add_triangle(a + 1, b + 1, b, part);
        }
    }
}

void add_card(plant_mesh_builder& out, const card& c, const uv_rect& region, const triangle_part& part) {
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    const glm::vec3 normal = glm::normalize(glm::cross(c.side, c.axis));
    const glm::vec3 half = c.side * (0.5f * c.width);
    const glm::vec3 tip = c.axis * c.length;
    out.vertices.push_back({c.base - half, normal, {region.min.x, region.max.y}});
    out.vertices.push_back({c.base + half, normal, {region.max.x, region.max.y}});
    out.vertices.push_back({c.base + half + tip, normal, {region.max.x, region.min.y}});
    out.vertices.push_back({c.base - half + tip, normal, {region.min.x, region.min.y}});
    out.add_triangle(base, base + 1, base + 2, part);
    out.add_triangle(base, base + 2, base + 3, part);
}

void add_strip(plant_mesh_builder& out, std::span<const glm::vec3> spine, std::span<const float> half_width,
               std::span<const glm::vec3> across, const uv_rect& region, const triangle_part& part) {
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    const std::size_t n = spine.size();
    for (std::size_t k = 0; k < n; ++k) {
        const glm::vec3 along = glm::normalize(spine[std::min(k + 1, n - 1)] - spine[k > 0 ? k - 1 : 0]);
        const glm::vec3 normal = glm::normalize(glm::cross(across[k], along));
        const float v = region.max.y + (region.min.y - region.max.y) * float(k) / float(n - 1);
        out.vertices.push_back({spine[k] - across[k] * half_width[k], normal, {region.min.x, v}});
        out.vertices.push_back({spine[k] + across[k] * half_width[k], normal, {region.max.x, v}});
    }
    for (std::uint32_t k = 0; k + 1 < n; ++k) {
        const std::uint32_t a = base + 2 * k;
        out.add_triangle(a, a + 1, a + 3, part);
        out.add_triangle(a, a + 3, a + 2, part);
    }
}

leaf_record card_record(const card& c, std::uint32_t parent_branch, part_kind kind) {
    return {c.base + c.axis * (0.5f * c.length), glm::normalize(glm::cross(c.side, c.axis)),
            std::max(c.length, c.width), parent_branch, kind};
}

mesh_data assemble_plant_mesh(plant_mesh_builder&& bark, plant_mesh_builder&& foliage) {
    mesh_data mesh;
    mesh.vertices = std::move(bark.vertices);
    mesh.indices = std::move(bark.indices);
    mesh.parts = std::move(bark.parts);
    mesh.leaves = std::move(bark.leaves);
    const auto bark_index_count = static_cast<std::uint32_t>(mesh.indices.size());
    const auto foliage_base = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), foliage.vertices.begin(), foliage.vertices.end());
    mesh.indices.reserve(mesh.indices.size() + foliage.indices.size());
    for (const std::uint32_t i : foliage.indices) mesh.indices.push_back(foliage_base + i);
    mesh.parts.insert(mesh.parts.end(), foliage.parts.begin(), foliage.parts.end());
    mesh.leaves.insert(mesh.leaves.end(), foliage.leaves.begin(), foliage.leaves.end());
    if (bark_index_count > 0) mesh.submeshes.push_back({0, bark_index_count, material_kind::bark});
    const auto foliage_count = static_cast<std::uint32_t>(foliage.indices.size());
    if (foliage_count > 0) mesh.submeshes.push_back({bark_index_count, foliage_count, material_kind::leaf});
    set_bounds(mesh);
    return mesh;
}

}  // namespace sylva
