#include "models/plant_model_io.h"

#include <stdexcept>
#include <string>

#include "models/bake_cache.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_magic = 0x4d505953;  // "SYPM"

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

}  // namespace

std::vector<std::byte> serialize_plant_model(const plant_model& model) {
    binary_writer out;
    out.pod(k_magic);
    out.pod(k_plant_model_format);
    out.text(model.name);
    for (const auto& lod : model.lods) write_mesh(out, lod);
    write_image(out, model.leaf_texture);
    write_image(out, model.bark_texture);
    out.pod(std::uint8_t(model.has_hierarchy ? 1 : 0));
    out.pod(model.source_unit_scale);
    return std::move(out.bytes());
}

plant_model deserialize_plant_model(std::span<const std::byte> bytes) {
    binary_reader in(bytes);
    if (in.pod<std::uint32_t>() != k_magic) throw std::runtime_error("bake cache entry: not a plant model");
    if (const auto version = in.pod<std::uint32_t>(); version != k_plant_model_format)
        throw std::runtime_error("bake cache entry: plant model format " + std::to_string(version) +
                                 ", this build reads " + std::to_string(k_plant_model_format));
    plant_model model;
    model.name = in.text();
    for (auto& lod : model.lods) lod = read_mesh(in);
    model.leaf_texture = read_image(in);
    model.bark_texture = read_image(in);
    model.has_hierarchy = in.pod<std::uint8_t>() != 0;
    model.source_unit_scale = in.pod<float>();
    if (!in.at_end()) throw std::runtime_error("bake cache entry: trailing bytes");
    return model;
}

}  // namespace sylva
