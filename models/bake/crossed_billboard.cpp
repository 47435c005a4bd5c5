#include "models/bake/crossed_billboard.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <stdexcept>

#include "models/bake/transfer_pages.h"

namespace sylva {
namespace {

struct extent {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};

// From the vertices, not mesh.bounds_*: imported and generated meshes agree on these.
extent extent_of(const mesh_data& mesh) {
    if (mesh.vertices.empty()) throw std::invalid_argument("crossed billboard: the full mesh has no vertices");
    extent e{mesh.vertices[0].position, mesh.vertices[0].position};
    for (const vertex& v : mesh.vertices) {
        e.min = glm::min(e.min, v.position);
        e.max = glm::max(e.max, v.position);
    }
    return e;
}

// Copies `src` into `dst` with its left edge at column `x0`.
void blit(image_rgba8& dst, const image_rgba8& src, std::uint32_t x0) {
    for (std::uint32_t y = 0; y < src.height; ++y)
        std::memcpy(dst.at(x0, y), src.at(0, y), std::size_t(src.width) * 4);
}

// One quad per plane: corners in the plane's lower-left, lower-right, upper-right, upper-left
// order (counter-clockwise seen from the plane's viewer side, so GL's front face), uvs into
// column `slot` of the atlas.
void add_quad(mesh_data& mesh, const billboard_plane& plane, std::size_t slot) {
    const auto base = std::uint32_t(mesh.vertices.size());
    const glm::vec3 n = plane.normal();
    const float s0 = float(slot) / float(k_crossed_billboard_quads);
    const float s1 = float(slot + 1) / float(k_crossed_billboard_quads);
    mesh.vertices.push_back({plane.origin, n, {s0, 1.0f}});
    mesh.vertices.push_back({plane.origin + plane.axis_u, n, {s1, 1.0f}});
    mesh.vertices.push_back({plane.origin + plane.axis_u + plane.axis_v, n, {s1, 0.0f}});
    mesh.vertices.push_back({plane.origin + plane.axis_v, n, {s0, 0.0f}});
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
}

}  // namespace

std::array<billboard_plane, k_crossed_billboard_quads> crossed_billboard_planes(const mesh_data& full) {
    const extent e = extent_of(full);
    const float height = std::max(e.max.y - e.min.y, 1e-4f);
    // Symmetric about the trunk so both quads cross at their centres; never thinner than a
    // thousandth of the height (a flat model still gets a valid plane).
    const float min_width = 1e-3f * height;
    const float half_x = std::max({std::abs(e.min.x), std::abs(e.max.x), 0.5f * min_width});
    const float half_z = std::max({std::abs(e.min.z), std::abs(e.max.z), 0.5f * min_width});
    const glm::vec3 up{0.0f, height, 0.0f};
    return {{
        {{-half_x, e.min.y, 0.0f}, {2.0f * half_x, 0.0f, 0.0f}, up},  // x-y plane, seen from +z
        {{0.0f, e.min.y, half_z}, {0.0f, 0.0f, -2.0f * half_z}, up},  // z-y plane, seen from +x
    }};
}

mesh_data facing_billboard_mesh(const mesh_data& crossed) {
    if (crossed.vertices.size() != 4 * k_crossed_billboard_quads || crossed.submeshes.size() != 1)
        throw std::invalid_argument("facing_billboard_mesh: not a crossed billboard's pair of quads");
    mesh_data out = crossed;
    out.submeshes[0].material = material_kind::facing_billboard;
    // Turned about the vertical axis, either quad sweeps the circle its half-width spans.
    const extent e = extent_of(out);
    const float reach = std::max({std::abs(e.min.x), std::abs(e.max.x), std::abs(e.min.z), std::abs(e.max.z)});
    out.bounds_min = {-reach, e.min.y, -reach};
    out.bounds_max = {reach, e.max.y, reach};
    return out;
}

crossed_billboard bake_crossed_billboard(const plant_model& model,
                                         const crossed_billboard_settings& settings,
                                         const radiance_transfer* transfer) {
    const mesh_data& full = model.lods[0];
    const auto planes = crossed_billboard_planes(full);
    billboard_bake_settings bake;
    bake.width = settings.resolution;
    bake.height = settings.resolution;
    bake.supersampling = settings.supersampling;
    const billboard_source source{&full, &model.leaf_texture, &model.bark_texture, {}, transfer};

    crossed_billboard out;
    for (image_rgba8* atlas : {&out.albedo, &out.normal}) {
        atlas->width = settings.resolution * std::uint32_t(k_crossed_billboard_quads);
        atlas->height = settings.resolution;
        atlas->texels.assign(std::size_t(atlas->width) * atlas->height * 4, 0);
    }
    if (transfer) out.transfer_pages = blank_transfer_pages(out.albedo.width, out.albedo.height);
    for (std::size_t q = 0; q < planes.size(); ++q) {
        const billboard_image image = bake_billboard(source, planes[q], bake);
        blit(out.albedo, image.albedo, std::uint32_t(q) * settings.resolution);
        blit(out.normal, image.normal, std::uint32_t(q) * settings.resolution);
        if (transfer)
            blit_transfer(out.transfer_pages, image, std::uint32_t(q) * settings.resolution, 0);
        add_quad(out.mesh, planes[q], q);
    }
    out.mesh.submeshes.push_back({0, std::uint32_t(out.mesh.indices.size()), material_kind::billboard});
    const extent e = extent_of(out.mesh);
    out.mesh.bounds_min = e.min;
    out.mesh.bounds_max = e.max;
    return out;
}

}  // namespace sylva
