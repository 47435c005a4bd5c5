#include "models/cache/plant_model_io.h"

#include <stdexcept>
#include <string>

#include "models/cache/bake_cache.h"
#include "models/cache/mesh_io.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_magic = 0x4d505953;  // "SYPM"

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
