#include "models/cache/mesh_io.h"

#include <cstring>
#include <stdexcept>

namespace sylva {
namespace {

// Writes records as array() would (count, then sizeof(T) bytes each) but with only the listed
// fields copied and every other byte (padding) zero. The compiler leaves padding undefined
// however records are built or copied, so a plain byte copy made equal meshes serialise to
// different bytes (and cache entries and determinism hashes that compare bytes differ).
template <class T, class... Field>
void write_records(binary_writer& out, const std::vector<T>& records, Field T::*... fields) {
    std::vector<std::byte> bytes(records.size() * sizeof(T));  // zero-filled
    for (std::size_t i = 0; i < records.size(); ++i) {
        std::byte* to = bytes.data() + i * sizeof(T);
        const T& record = records[i];
        const auto* from = reinterpret_cast<const std::byte*>(&record);
        (std::memcpy(to + (reinterpret_cast<const std::byte*>(&(record.*fields)) - from), &(record.*fields),
                     sizeof(record.*fields)),
         ...);
    }
    out.pod(std::uint64_t(records.size()));
    out.raw(bytes);
}

}  // namespace

void write_mesh(binary_writer& out, const mesh_data& mesh) {
    out.array(mesh.vertices);
    out.array(mesh.indices);
    write_records(out, mesh.submeshes, &submesh::first_index, &submesh::index_count, &submesh::material);
    write_records(out, mesh.parts, &triangle_part::branch, &triangle_part::level, &triangle_part::kind,
                  &triangle_part::parent_branch);
    write_records(out, mesh.leaves, &leaf_record::center, &leaf_record::normal, &leaf_record::size,
                  &leaf_record::parent_branch, &leaf_record::kind);
    out.pod(mesh.bounds_min);
    out.pod(mesh.bounds_max);
}

mesh_data read_mesh(binary_reader& in) {
    mesh_data mesh;
    mesh.vertices = in.array<vertex>();
    mesh.indices = in.array<std::uint32_t>();
    mesh.submeshes = in.array<submesh>();
    mesh.parts = in.array<triangle_part>();
    mesh.leaves = in.array<leaf_record>();
    mesh.bounds_min = in.pod<glm::vec3>();
    mesh.bounds_max = in.pod<glm::vec3>();
    for (std::uint32_t i : mesh.indices)
        if (i >= mesh.vertices.size()) throw std::runtime_error("bake cache entry: mesh index out of range");
    return mesh;
}

void write_image(binary_writer& out, const image_rgba8& image) {
    out.pod(image.width);
    out.pod(image.height);
    out.array(image.texels);
}

image_rgba8 read_image(binary_reader& in) {
    image_rgba8 image;
    image.width = in.pod<std::uint32_t>();
    image.height = in.pod<std::uint32_t>();
    image.texels = in.array<std::uint8_t>();
    if (image.texels.size() != std::size_t(image.width) * image.height * 4)
        throw std::runtime_error("bake cache entry: image size does not match its texels");
    return image;
}

}  // namespace sylva
