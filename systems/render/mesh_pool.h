#pragma once
// Every mesh of the scene in one shared vertex buffer and one shared index buffer, so a whole
// pass is one vertex array binding and a handful of multi-draw-indirect calls. A third buffer,
// parallel to the vertices, streams each vertex's SH transfer (models/mesh.h vertex_transfer);
// it exists once some mesh has transfer, and vertices without any read zeros from it.
#include <cstdint>
#include <vector>

#include "models/mesh.h"
#include "systems/render/gl_objects.h"
#include "resources/scene_assets.h"

namespace sylva::render {

struct gpu_submesh {
    std::uint32_t first_index = 0;  // in the shared index buffer
    std::uint32_t index_count = 0;
    std::int32_t base_vertex = 0;   // in the shared vertex buffer
    material_kind material = material_kind::bark;
    lighting_variant lighting = lighting_variant::normal_mapped;
};

struct gpu_mesh {
    std::vector<gpu_submesh> submeshes;
    std::uint32_t triangle_count = 0;  // triangle meshes only
    primitive_kind primitive = primitive_kind::triangles;
};

class mesh_pool {
public:
    mesh_pool();
    // Uploads the mesh; the returned id is its index (stable for the pool's lifetime).
    // `lighting` chooses the shader its submeshes are drawn with; sh needs mesh.transfer.
    std::uint16_t add(const mesh_data& mesh,
                      lighting_variant lighting = lighting_variant::normal_mapped);
    // Uploads the indices and submeshes of `mesh` (a triangle list without vertices of its own)
    // over the vertices of mesh `vertices_of`. LoDF's trunk and foliage (Rebollo 2006 Eq. 3,
    // |V^r| = V) draw every level from the full mesh's vertices this way.
    std::uint16_t add_indices(std::uint16_t vertices_of, const mesh_data& mesh,
                              lighting_variant lighting = lighting_variant::normal_mapped);
    const gpu_mesh& get(std::uint16_t id) const { return m_meshes.at(id); }
    std::size_t size() const { return m_meshes.size(); }
    GLuint vertex_array() const { return m_vao.id(); }
    std::uint64_t uploaded_bytes() const { return m_uploaded_bytes; }

private:
    void reserve(std::size_t vertex_count, std::size_t index_count);
    void enable_transfer();

    gl_vertex_array m_vao;
    gl_buffer m_vertices;
    gl_buffer m_indices;
    gl_buffer m_transfer;  // vertex_transfer per vertex, m_vertex_capacity of them once used
    std::size_t m_vertex_capacity = 0;
    std::size_t m_index_capacity = 0;
    std::size_t m_vertex_count = 0;
    std::size_t m_index_count = 0;
    std::uint64_t m_uploaded_bytes = 0;
    std::vector<gpu_mesh> m_meshes;
};

}  // namespace sylva::render
