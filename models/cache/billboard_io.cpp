#include "models/cache/billboard_io.h"

#include <stdexcept>
#include <string>

#include "models/cache/bake_cache.h"
#include "models/cache/mesh_io.h"
#include "models/bake/transfer_pages.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_magic = 0x42435953;  // "SYCB"

}  // namespace

std::vector<std::byte> serialize_crossed_billboard(const crossed_billboard& billboard) {
    binary_writer out;
    out.pod(k_magic);
    out.pod(k_crossed_billboard_format);
    write_mesh(out, billboard.mesh);
    write_image(out, billboard.albedo);
    write_image(out, billboard.normal);
    write_transfer_pages(out, billboard.transfer_pages);
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
    billboard.transfer_pages =
        read_transfer_pages(in, billboard.albedo.width, billboard.albedo.height, "crossed billboard");
    if (!in.at_end()) throw std::runtime_error("bake cache entry: trailing bytes");
    return billboard;
}

}  // namespace sylva
