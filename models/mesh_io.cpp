#include "models/mesh_io.h"

#include <stdexcept>

namespace sylva {

void write_mesh(binary_writer& out, const mesh_data& mesh) {
    out.array(mesh.vertices);
    out.array(mesh.indices);
    out.array(mesh.submeshes);
    out.array(mesh.parts);
    out.array(mesh.leaves);
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
