#include "models/bake/crossed_billboard.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <limits>
#include <stdexcept>
#include <string>

#include "ecs/parallel.h"
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

// The atlas's columns: the two crossed quads' images, R wide each, an empty R/2, the facing
// views, R/2 wide each, by elevation and then quad, and an empty R/2 (the header's layout).
std::uint32_t facing_column(std::size_t quad, std::size_t elevation, std::uint32_t resolution) {
    return std::uint32_t(2 * k_crossed_billboard_quads + 1 + 2 * elevation + quad) *
           (resolution / 2);
}

// One quad per plane: corners in the plane's lower-left, lower-right, upper-right, upper-left
// order (counter-clockwise seen from the plane's viewer side, so GL's front face), texture
// coordinates from `lower_left` to `upper_right`.
void add_quad(mesh_data& mesh, const billboard_plane& plane, glm::vec2 lower_left,
              glm::vec2 upper_right) {
    const auto base = std::uint32_t(mesh.vertices.size());
    const glm::vec3 n = plane.normal();
    mesh.vertices.push_back({plane.origin, n, lower_left});
    mesh.vertices.push_back({plane.origin + plane.axis_u, n, {upper_right.x, lower_left.y}});
    mesh.vertices.push_back({plane.origin + plane.axis_u + plane.axis_v, n, upper_right});
    mesh.vertices.push_back({plane.origin + plane.axis_v, n, {lower_left.x, upper_right.y}});
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
}

// A crossed quad: its image in the atlas's column `slot`.
void add_quad(mesh_data& mesh, const billboard_plane& plane, std::size_t slot) {
    const float s0 = float(slot) / float(k_crossed_billboard_atlas_widths);
    const float s1 = float(slot + 1) / float(k_crossed_billboard_atlas_widths);
    add_quad(mesh, plane, {s0, 1.0f}, {s1, 0.0f});
}

}  // namespace

std::vector<std::uint32_t> crossed_billboard_atlas_columns(std::uint32_t resolution) {
    std::vector<std::uint32_t> columns{0, std::uint32_t(k_crossed_billboard_quads) * resolution};
    for (std::size_t k = 0; k < k_facing_elevations_deg.size(); ++k)
        for (std::size_t q = 0; q < k_crossed_billboard_quads; ++q)
            columns.push_back(facing_column(q, k, resolution));
    columns.push_back(
        facing_column(0, k_facing_elevations_deg.size(), resolution));  // the last empty one
    columns.push_back(k_crossed_billboard_atlas_widths * resolution);
    return columns;
}

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

billboard_plane facing_view_plane(
    const std::array<billboard_plane, k_crossed_billboard_quads>& crossed, std::size_t quad,
    std::size_t elevation) {
    if (quad >= k_crossed_billboard_quads || elevation >= k_facing_elevations_deg.size())
        throw std::invalid_argument("facing_view_plane: no such view");
    const float w = std::max(glm::length(crossed[0].axis_u), glm::length(crossed[1].axis_u)) * 0.5f;
    const float bottom = crossed[0].origin.y;
    const float top = bottom + glm::length(crossed[0].axis_v);
    const float middle = 0.5f * (bottom + top);
    const float e = glm::radians(k_facing_elevations_deg[elevation]);
    const float c = std::cos(e), s = std::sin(e);
    const glm::vec3 normal = glm::normalize(crossed[quad].normal());  // +z or +x
    const glm::vec3 across = glm::normalize(crossed[quad].axis_u);    // +x or -z
    const glm::vec3 tilted_up = glm::vec3(0.0f, c, 0.0f) - normal * s;
    const float half =
        0.5f * (top - bottom) * c + w * s;  // along tilted_up, either side of the middle
    return {glm::vec3(0.0f, middle, 0.0f) - w * across - half * tilted_up, 2.0f * w * across,
            2.0f * half * tilted_up};
}

mesh_data facing_billboard_mesh(const mesh_data& crossed) {
    if (crossed.vertices.size() != 4 * k_crossed_billboard_quads || crossed.submeshes.size() != 1)
        throw std::invalid_argument("facing_billboard_mesh: not a crossed billboard's pair of quads");
    // The pair's planes back from its corners (add_quad's order: origin, +u, +u+v, +v).
    std::array<billboard_plane, k_crossed_billboard_quads> planes;
    for (std::size_t q = 0; q < planes.size(); ++q) {
        const vertex* v = &crossed.vertices[4 * q];
        planes[q] = {v[0].position, v[1].position - v[0].position, v[3].position - v[0].position};
    }
    mesh_data out;
    // The elevation-0 views' columns as fractions of the atlas (at R = 2 a view is one texel).
    const auto s_of = [](std::size_t column) { return float(column) / float(2 * k_crossed_billboard_atlas_widths); };
    for (std::size_t q = 0; q < planes.size(); ++q)
        add_quad(out, facing_view_plane(planes, q, 0), {s_of(facing_column(q, 0, 2)), 1.0f},
                 {s_of(facing_column(q, 0, 2) + 1), 0.0f});
    // The eye's elevation is measured from the plant's middle, the same point for all four
    // corners: each vertex carries its height as its normal's y (the quads' normals are
    // horizontal, and the shader replaces them by the tilted view's).
    const float middle = planes[0].origin.y + 0.5f * planes[0].axis_v.y;
    for (vertex& v : out.vertices) v.normal.y = middle;
    out.submeshes.push_back(
        {0, std::uint32_t(out.indices.size()), material_kind::facing_billboard});
    // Turned about the vertical axis and tilted back, a shown quad stays within the circle its
    // corners sweep at any of the elevations.
    float reach = 0.0f, low = std::numeric_limits<float>::max(),
          high = std::numeric_limits<float>::lowest();
    for (std::size_t k = 0; k < k_facing_elevations_deg.size(); ++k) {
        const billboard_plane p = facing_view_plane(planes, 0, k);
        for (const glm::vec3 corner :
             {p.origin, p.origin + p.axis_u, p.origin + p.axis_v, p.origin + p.axis_u + p.axis_v}) {
            reach = std::max(reach, glm::length(glm::vec2(corner.x, corner.z)));
            low = std::min(low, corner.y);
            high = std::max(high, corner.y);
        }
    }
    out.bounds_min = {-reach, low, -reach};
    out.bounds_max = {reach, high, reach};
    return out;
}

crossed_billboard bake_crossed_billboard(const plant_model& model,
                                         const crossed_billboard_settings& settings,
                                         const radiance_transfer* transfer) {
    if (settings.resolution < 2 || settings.resolution % 2 != 0)
        throw std::invalid_argument("crossed billboard: resolution " +
                                    std::to_string(settings.resolution) +
                                    " must be even (the facing views are half as wide)");
    const mesh_data& full = model.lods[0];
    const auto planes = crossed_billboard_planes(full);
    billboard_bake_settings bake;
    bake.width = settings.resolution;
    bake.height = settings.resolution;
    bake.supersampling = settings.supersampling;
    const billboard_source source{&full, &model.leaf_texture, &model.bark_texture, {}, transfer};

    crossed_billboard out;
    for (image_rgba8* atlas : {&out.albedo, &out.normal}) {
        atlas->width = settings.resolution * k_crossed_billboard_atlas_widths;
        atlas->height = settings.resolution;
        atlas->texels.assign(std::size_t(atlas->width) * atlas->height * 4, 0);
    }
    if (transfer) out.transfer_pages = blank_transfer_pages(out.albedo.width, out.albedo.height);
    // The two crossed quads and the eight facing views, each into its own columns: baked in
    // parallel (no two touch the same texels; each bake is deterministic). On the 135 k-triangle
    // broadleaf_hd the ten took 1.23 s one after another and 0.61 s on 2 cores; the two quads
    // alone, the whole bake before the views, 0.34 s.
    struct view {
        billboard_plane plane;
        billboard_bake_settings settings;
        std::uint32_t column;
    };
    std::vector<view> views;
    for (std::size_t q = 0; q < planes.size(); ++q) {
        views.push_back({planes[q], bake, std::uint32_t(q) * settings.resolution});
        add_quad(out.mesh, planes[q], q);
    }
    billboard_bake_settings facing = bake;
    facing.width = settings.resolution / 2;
    for (std::size_t k = 0; k < k_facing_elevations_deg.size(); ++k)
        for (std::size_t q = 0; q < planes.size(); ++q)
            views.push_back({facing_view_plane(planes, q, k), facing, facing_column(q, k, settings.resolution)});
    ecs::parallel_for_each_index(views.size(), [&](std::size_t i) {
        const billboard_image image = bake_billboard(source, views[i].plane, views[i].settings);
        blit(out.albedo, image.albedo, views[i].column);
        blit(out.normal, image.normal, views[i].column);
        if (transfer) blit_transfer(out.transfer_pages, image, views[i].column, 0);
    });
    out.mesh.submeshes.push_back({0, std::uint32_t(out.mesh.indices.size()), material_kind::billboard});
    const extent e = extent_of(out.mesh);
    out.mesh.bounds_min = e.min;
    out.mesh.bounds_max = e.max;
    return out;
}

}  // namespace sylva
