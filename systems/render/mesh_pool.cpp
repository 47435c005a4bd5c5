#include "systems/render/mesh_pool.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace sylva::render {
namespace {

constexpr GLuint k_vertex_binding = 0;
constexpr GLuint k_transfer_binding = 2;  // 1 is the instance records (renderer.cpp)
constexpr GLuint k_first_transfer_attribute = 5;

// Grows a buffer to `new_bytes`, keeping the first `used_bytes` (GL 4.5 buffers are immutable).
gl_buffer grow(gl_buffer old, std::size_t used_bytes, std::size_t new_bytes) {
    gl_buffer bigger = make_buffer();
    glNamedBufferStorage(bigger.id(), GLsizeiptr(new_bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
    if (old && used_bytes)
        glCopyNamedBufferSubData(old.id(), bigger.id(), 0, 0, GLsizeiptr(used_bytes));
    return bigger;
}

}  // namespace

mesh_pool::mesh_pool() : m_vao(make_vertex_array()) {
    // Layout mirrored from models/mesh.h `vertex` and shaders/common.glsl.
    const GLuint vao = m_vao.id();
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(vertex, position));
    glVertexArrayAttribFormat(vao, 1, 3, GL_FLOAT, GL_FALSE, offsetof(vertex, normal));
    glVertexArrayAttribFormat(vao, 2, 2, GL_FLOAT, GL_FALSE, offsetof(vertex, uv));
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribBinding(vao, a, k_vertex_binding);
    }
    // vertex_transfer: five vec4s of half floats (shaders/surface.vert locations 5..9).
    for (GLuint a = 0; a < 5; ++a) {
        glVertexArrayAttribFormat(vao, k_first_transfer_attribute + a, 4, GL_HALF_FLOAT, GL_FALSE,
                                  a * 8);
        glVertexArrayAttribBinding(vao, k_first_transfer_attribute + a, k_transfer_binding);
    }
    reserve(1 << 16, 1 << 18);
}

void mesh_pool::enable_transfer() {
    if (m_transfer) return;
    m_transfer = grow({}, 0, m_vertex_capacity * sizeof(vertex_transfer));
    std::vector<vertex_transfer> zeros(m_vertex_count);
    if (!zeros.empty())
        glNamedBufferSubData(m_transfer.id(), 0, GLsizeiptr(zeros.size() * sizeof(vertex_transfer)),
                             zeros.data());
    glVertexArrayVertexBuffer(m_vao.id(), k_transfer_binding, m_transfer.id(), 0,
                              sizeof(vertex_transfer));
    for (GLuint a = 0; a < 5; ++a)
        glEnableVertexArrayAttrib(m_vao.id(), k_first_transfer_attribute + a);
}

void mesh_pool::reserve(std::size_t vertex_count, std::size_t index_count) {
    if (vertex_count > m_vertex_capacity) {
        std::size_t capacity = std::max(vertex_count, m_vertex_capacity * 2);
        m_vertices = grow(std::move(m_vertices), m_vertex_count * sizeof(vertex),
                          capacity * sizeof(vertex));
        if (m_transfer) {
            m_transfer = grow(std::move(m_transfer), m_vertex_count * sizeof(vertex_transfer),
                              capacity * sizeof(vertex_transfer));
            glVertexArrayVertexBuffer(m_vao.id(), k_transfer_binding, m_transfer.id(), 0,
                                      sizeof(vertex_transfer));
        }
        m_vertex_capacity = capacity;
        glVertexArrayVertexBuffer(m_vao.id(), k_vertex_binding, m_vertices.id(), 0, sizeof(vertex));
    }
    if (index_count > m_index_capacity) {
        std::size_t capacity = std::max(index_count, m_index_capacity * 2);
        m_indices = grow(std::move(m_indices), m_index_count * sizeof(std::uint32_t),
                         capacity * sizeof(std::uint32_t));
        m_index_capacity = capacity;
        glVertexArrayElementBuffer(m_vao.id(), m_indices.id());
    }
}

std::uint16_t mesh_pool::add(const mesh_data& mesh, lighting_variant lighting) {
    if (m_meshes.size() >= std::numeric_limits<std::uint16_t>::max())
        throw std::runtime_error("mesh_pool: more than 65535 meshes");
    if (!mesh.transfer.empty() && mesh.transfer.size() != mesh.vertices.size())
        throw std::logic_error("mesh_pool: a mesh's transfer must have one record per vertex");
    // Billboards read their transfer from pages; every other SH-lit mesh streams it.
    if (uses_transfer(lighting) && mesh.transfer.empty() && !mesh.vertices.empty() &&
        !mesh.submeshes.empty() && mesh.submeshes[0].material != material_kind::billboard_cloud &&
        !is_billboard(mesh.submeshes[0].material))
        throw std::logic_error("mesh_pool: an SH-lit mesh needs its transfer");
    if (!mesh.transfer.empty()) enable_transfer();
    reserve(m_vertex_count + mesh.vertices.size(), m_index_count + mesh.indices.size());
    const auto vertex_bytes = GLsizeiptr(mesh.vertices.size() * sizeof(vertex));
    const auto index_bytes = GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t));
    glNamedBufferSubData(m_vertices.id(), GLintptr(m_vertex_count * sizeof(vertex)), vertex_bytes,
                         mesh.vertices.data());
    glNamedBufferSubData(m_indices.id(), GLintptr(m_index_count * sizeof(std::uint32_t)),
                         index_bytes, mesh.indices.data());
    m_uploaded_bytes += std::uint64_t(vertex_bytes + index_bytes);
    if (m_transfer) {
        // Zeros for a mesh without transfer: the buffer's storage starts undefined.
        std::vector<vertex_transfer> zeros;
        if (mesh.transfer.empty()) zeros.resize(mesh.vertices.size());
        const auto& records = mesh.transfer.empty() ? zeros : mesh.transfer;
        const auto transfer_bytes = GLsizeiptr(records.size() * sizeof(vertex_transfer));
        glNamedBufferSubData(m_transfer.id(), GLintptr(m_vertex_count * sizeof(vertex_transfer)),
                             transfer_bytes, records.data());
        m_uploaded_bytes += std::uint64_t(transfer_bytes);
    }

    gpu_mesh gpu;
    gpu.primitive = mesh.primitive;
    for (const auto& sub : mesh.submeshes) {
        gpu.submeshes.push_back({std::uint32_t(m_index_count + sub.first_index), sub.index_count,
                                 std::int32_t(m_vertex_count), sub.material, lighting});
        if (mesh.primitive == primitive_kind::triangles) gpu.triangle_count += sub.index_count / 3;
    }
    m_vertex_count += mesh.vertices.size();
    m_index_count += mesh.indices.size();
    m_meshes.push_back(std::move(gpu));
    return std::uint16_t(m_meshes.size() - 1);
}

std::uint16_t mesh_pool::add_indices(std::uint16_t vertices_of, const mesh_data& mesh, lighting_variant lighting) {
    if (m_meshes.size() >= std::numeric_limits<std::uint16_t>::max())
        throw std::runtime_error("mesh_pool: more than 65535 meshes");
    const gpu_mesh& source = m_meshes.at(vertices_of);
    if (source.submeshes.empty() || source.primitive != primitive_kind::triangles || !mesh.vertices.empty() ||
        mesh.primitive != primitive_kind::triangles)
        throw std::logic_error("mesh_pool: an index list goes over a triangle mesh's vertices and has none");
    const std::int32_t base_vertex = source.submeshes[0].base_vertex;
    reserve(m_vertex_count, m_index_count + mesh.indices.size());
    const auto index_bytes = GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t));
    glNamedBufferSubData(m_indices.id(), GLintptr(m_index_count * sizeof(std::uint32_t)), index_bytes,
                         mesh.indices.data());
    m_uploaded_bytes += std::uint64_t(index_bytes);
    gpu_mesh gpu;
    for (const submesh& sub : mesh.submeshes) {
        gpu.submeshes.push_back(
            {std::uint32_t(m_index_count + sub.first_index), sub.index_count, base_vertex, sub.material, lighting});
        gpu.triangle_count += sub.index_count / 3;
    }
    m_index_count += mesh.indices.size();
    m_meshes.push_back(std::move(gpu));
    return std::uint16_t(m_meshes.size() - 1);
}

}  // namespace sylva::render
