#pragma once
// CPU-side meshes as produced by the generators (and later the glTF importer): one interleaved
// vertex array, one index array, and sub-meshes that each use one material.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace sylva {

// Mirrored by the vertex input layout in shaders/common.glsl (locations 0..2).
struct vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};
};
static_assert(sizeof(vertex) == 32);

// How a material is shaded; the renderer picks its pipeline from this.
enum class material_kind : std::uint8_t {
    bark,    // opaque, textured
    leaf,    // alpha-tested (discard below 0.5), double-sided, translucent-ish diffuse
    ground,  // opaque terrain, tiled texture
};

struct submesh {
    std::uint32_t first_index = 0;
    std::uint32_t index_count = 0;
    material_kind material = material_kind::bark;
};

struct mesh_data {
    std::vector<vertex> vertices;
    std::vector<std::uint32_t> indices;  // triangle list
    std::vector<submesh> submeshes;
    glm::vec3 bounds_min{0.0f};
    glm::vec3 bounds_max{0.0f};

    std::size_t triangle_count() const { return indices.size() / 3; }
};

}  // namespace sylva
