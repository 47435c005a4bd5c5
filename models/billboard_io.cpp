#include "models/billboard_io.h"

#include <stdexcept>
#include <string>

#include "models/bake_cache.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_magic = 0x42435953;  // "SYCB"

// The billboard mesh carries no parts or leaf records: only what the renderer draws.
void write_mesh(binary_writer& out, const mesh_data& mesh) {
    out.array(mesh.vertices);
    out.array(mesh.indices);
    out.array(mesh.submeshes);
    out.pod(mesh.bounds_min);
    out.pod(mesh.bounds_max);
}

mesh_data read_mesh(binary_reader& in) {
    mesh_data mesh;
    mesh.vertices = in.array<vertex>();
    mesh.indices = in.array<std::uint32_t>();
    mesh.submeshes = in.array<submesh>();
    mesh.bounds_min = in.pod<glm::vec3>();
    mesh.bounds_max = in.pod<glm::vec3>();
    for (std::uint32_t i : mesh.indices)
        if (i >= mesh.vertices.size()) throw std::runtime_error("bake cache entry: billboard index out of range");
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
        throw std::runtime_error("bake cache entry: billboard image size does not match its texels");
    return image;
}

}  // namespace

std::vector<std::byte> serialize_crossed_billboard(const crossed_billboard& billboard) {
    binary_writer out;
    out.pod(k_magic);
    out.pod(k_crossed_billboard_format);
    write_mesh(out, billboard.mesh);
    write_image(out, billboard.albedo);
    write_image(out, billboard.normal);
    return std::move(out.bytes());
}

crossed_billboard deserialize_crossed_billboard(std::span<const std::byte> bytes) {
    binary_reader in(bytes);
    if (in.pod<std::uint32_t>() != k_magic) throw std::runtime_error("bake cache entry: not a crossed billboard");
    if (const auto version = in.pod<std::uint32_t>(); version != k_crossed_billboard_format)
        throw std::runtime_error("bake cache entry: crossed billboard format " + std::to_string(version) +
                                 ", this build reads " + std::to_string(k_crossed_billboard_format));
    crossed_billboard billboard;
    billboard.mesh = read_mesh(in);
    billboard.albedo = read_image(in);
    billboard.normal = read_image(in);
    if (billboard.albedo.width != billboard.normal.width || billboard.albedo.height != billboard.normal.height)
        throw std::runtime_error("bake cache entry: billboard albedo and normal atlases differ in size");
    if (!in.at_end()) throw std::runtime_error("bake cache entry: trailing bytes");
    return billboard;
}

}  // namespace sylva
