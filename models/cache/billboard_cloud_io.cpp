#include "models/cache/billboard_cloud_io.h"

#include <stdexcept>
#include <string>

#include "models/cache/bake_cache.h"
#include "models/cache/mesh_io.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_magic = 0x43425953;  // "SYBC"

void write_vec3(binary_writer& out, glm::vec3 v) {
    out.pod(v.x);
    out.pod(v.y);
    out.pod(v.z);
}

glm::vec3 read_vec3(binary_reader& in) {
    const auto x = in.pod<float>();
    const auto y = in.pod<float>();
    return {x, y, in.pod<float>()};
}

void write_box(binary_writer& out, const oriented_box& box) {
    write_vec3(out, box.center);
    for (const glm::vec3& axis : box.axes) write_vec3(out, axis);
    write_vec3(out, box.half_extent);
}

oriented_box read_box(binary_reader& in) {
    oriented_box box;
    box.center = read_vec3(in);
    for (glm::vec3& axis : box.axes) axis = read_vec3(in);
    box.half_extent = read_vec3(in);
    return box;
}

}  // namespace

std::vector<std::byte> serialize_billboard_cloud(const billboard_cloud& cloud) {
    binary_writer out;
    out.pod(k_magic);
    out.pod(k_billboard_cloud_format);
    out.pod(std::uint8_t(cloud.method));
    out.pod(std::int32_t(cloud.branching_level));
    out.pod(cloud.texels_per_metre);
    write_mesh(out, cloud.mesh);
    out.pod(std::uint64_t(cloud.clusters.size()));
    for (const cloud_cluster& c : cloud.clusters) {
        write_box(out, c.box);
        out.pod(c.pca_volume);
        out.pod(c.triangles);
        out.pod(std::uint8_t(c.foliage));
    }
    out.pod(std::uint64_t(cloud.billboards.size()));
    for (const cloud_billboard& b : cloud.billboards) {
        write_vec3(out, b.plane.origin);
        write_vec3(out, b.plane.axis_u);
        write_vec3(out, b.plane.axis_v);
        out.pod(b.cluster);
        out.pod(std::uint8_t(b.face));
        out.pod(b.rect.x);
        out.pod(b.rect.y);
        out.pod(b.rect.width);
        out.pod(b.rect.height);
    }
    out.pod(cloud.atlas_width);
    out.pod(cloud.atlas_height);
    out.pod(k_cloud_atlas_pages);
    for (const image_rgba8& page : cloud.pages) write_image(out, page);
    write_transfer_pages(out, cloud.transfer_pages);
    return std::move(out.bytes());
}

billboard_cloud deserialize_billboard_cloud(std::span<const std::byte> bytes) {
    binary_reader in(bytes);
    if (in.pod<std::uint32_t>() != k_magic) throw std::runtime_error("bake cache entry: not a billboard cloud");
    if (const auto version = in.pod<std::uint32_t>(); version != k_billboard_cloud_format)
        throw std::runtime_error("bake cache entry: billboard cloud format " + std::to_string(version) +
                                 ", this build reads " + std::to_string(k_billboard_cloud_format));
    billboard_cloud cloud;
    const auto method = in.pod<std::uint8_t>();
    if (method > std::uint8_t(clustering_method::geometric))
        throw std::runtime_error("bake cache entry: unknown clustering method " + std::to_string(method));
    cloud.method = clustering_method(method);
    cloud.branching_level = in.pod<std::int32_t>();
    cloud.texels_per_metre = in.pod<float>();
    cloud.mesh = read_mesh(in);
    const auto clusters = in.pod<std::uint64_t>();
    if (clusters > bytes.size()) throw std::runtime_error("bake cache entry: billboard cloud cluster count is corrupt");
    cloud.clusters.resize(clusters);
    for (cloud_cluster& c : cloud.clusters) {
        c.box = read_box(in);
        c.pca_volume = in.pod<float>();
        c.triangles = in.pod<std::uint32_t>();
        c.foliage = in.pod<std::uint8_t>() != 0;
    }
    const auto billboards = in.pod<std::uint64_t>();
    if (billboards > bytes.size()) throw std::runtime_error("bake cache entry: billboard count is corrupt");
    cloud.billboards.resize(billboards);
    for (cloud_billboard& b : cloud.billboards) {
        b.plane.origin = read_vec3(in);
        b.plane.axis_u = read_vec3(in);
        b.plane.axis_v = read_vec3(in);
        b.cluster = in.pod<std::uint32_t>();
        const auto face = in.pod<std::uint8_t>();
        if (face > std::uint8_t(box_face::bc) || b.cluster >= clusters)
            throw std::runtime_error("bake cache entry: billboard with a bad face or cluster");
        b.face = box_face(face);
        b.rect.x = in.pod<std::uint32_t>();
        b.rect.y = in.pod<std::uint32_t>();
        b.rect.width = in.pod<std::uint32_t>();
        b.rect.height = in.pod<std::uint32_t>();
    }
    cloud.atlas_width = in.pod<std::uint32_t>();
    cloud.atlas_height = in.pod<std::uint32_t>();
    if (in.pod<std::uint32_t>() != k_cloud_atlas_pages)
        throw std::runtime_error("bake cache entry: billboard cloud atlas page count differs");
    for (image_rgba8& page : cloud.pages) {
        page = read_image(in);
        if (page.width != cloud.atlas_width || page.height != cloud.atlas_height)
            throw std::runtime_error("bake cache entry: billboard cloud atlas pages differ in size");
    }
    cloud.transfer_pages = read_transfer_pages(in, cloud.atlas_width, cloud.atlas_height, "billboard cloud");
    if (!in.at_end()) throw std::runtime_error("bake cache entry: trailing bytes");
    return cloud;
}

}  // namespace sylva
