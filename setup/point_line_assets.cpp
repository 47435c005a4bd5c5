#include "setup/point_line_assets.h"

#include <stdexcept>
#include <unordered_map>

namespace sylva {
namespace {

void scale_vertices(std::vector<vertex>& vertices, float scale) {
    for (auto& v : vertices) v.position *= scale;
}

// Point and line samples are shaded with the leaf or the bark texture (systems/render/passes/sample_draw.cpp).
material_kind sample_material(material_kind m) {
    return m == material_kind::leaf || m == material_kind::billboard ? material_kind::leaf : material_kind::bark;
}

}  // namespace

mesh_data primitive_mesh(std::vector<vertex> vertices, primitive_kind primitive,
                         material_kind material, std::vector<vertex_transfer> transfer) {
    if (!transfer.empty() && transfer.size() != vertices.size())
        throw std::logic_error("primitive_mesh: transfer records must match the vertices");
    mesh_data mesh;
    mesh.transfer = std::move(transfer);
    mesh.primitive = primitive;
    mesh.indices.resize(vertices.size());
    for (std::uint32_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = i;
    mesh.vertices = std::move(vertices);
    mesh.submeshes.push_back({0, std::uint32_t(mesh.indices.size()), sample_material(material)});
    return mesh;
}

std::uint16_t add_sample_mesh(scene_assets& assets, mesh_data mesh, std::uint32_t primitives) {
    if (assets.meshes.size() >= 0xFFFFu)
        throw std::runtime_error("scene: more than 65,535 meshes (point/line parts and tile sets included)");
    const auto id = std::uint16_t(assets.meshes.size());
    assets.library.meshes.push_back({primitives, representation::points, mesh.primitive});
    assets.meshes.push_back(std::move(mesh));
    return id;
}

mesh_data extract_triangles(const mesh_data& mesh, std::uint32_t first_index, std::uint32_t index_count,
                            material_kind material) {
    mesh_data out;
    std::unordered_map<std::uint32_t, std::uint32_t> remap;
    out.indices.reserve(index_count);
    for (std::uint32_t i = first_index; i < first_index + index_count; ++i) {
        const std::uint32_t source = mesh.indices.at(i);
        const auto [it, added] = remap.try_emplace(source, std::uint32_t(out.vertices.size()));
        if (added) {
            out.vertices.push_back(mesh.vertices.at(source));
            if (!mesh.transfer.empty()) out.transfer.push_back(mesh.transfer.at(source));
        }
        out.indices.push_back(it->second);
    }
    out.submeshes.push_back({0, index_count, material});
    return out;
}

namespace {

// Adds the parts of one cell to the library; returns the index of the first.
std::uint32_t add_cell_parts(scene_assets& assets, const point_line_model& model,
                             const lod_cell& cell, float scale, float importance,
                             const point_line_model& with_transfer,
                             const point_line_records* transfer) {
    if (cell.part_count > k_max_cell_parts) throw std::runtime_error("point/line model: too many parts in a cell");
    const auto first = std::uint32_t(assets.library.lod_parts.size());
    for (std::uint32_t i = cell.first_part; i < cell.first_part + cell.part_count; ++i) {
        const lod_part& part = model.parts.at(i);
        lod_part_entry e;
        e.primitive = part.primitive;
        e.importance = part.importance * importance;
        e.area_m2 = part.area_m2 * scale * scale;
        e.center = part.center * scale;
        e.triangle_count = part.triangle_count;
        e.line_length_m = part.line_length_m * scale;
        e.line_error_m = part.line_error_m * scale;

        mesh_data triangles = extract_triangles(with_transfer.triangles, part.first_index,
                                                3 * part.triangle_count, part.material);
        scale_vertices(triangles.vertices, scale);
        e.mesh_triangles = add_sample_mesh(assets, std::move(triangles), part.triangle_count);

        std::vector<vertex> vertices;
        std::vector<vertex_transfer> records;
        auto records_of = [&](const std::vector<vertex_transfer>& all, std::size_t start,
                              std::size_t count) {
            if (transfer)
                records.assign(all.begin() + std::ptrdiff_t(start),
                               all.begin() + std::ptrdiff_t(start + count));
        };
        if (part.primitive == lod_primitive::points) {
            e.primitive_count = part.point_count;
            e.first_after = std::uint32_t(assets.library.points_after.size());
            const auto after = model.points_after.begin() + part.first_after;
            assets.library.points_after.insert(assets.library.points_after.end(), after,
                                               after + part.triangle_count + 1);
            vertices.assign(model.points.begin() + part.first_point,
                            model.points.begin() + part.first_point + part.point_count);
            if (transfer) records_of(transfer->points, part.first_point, part.point_count);
        } else {
            e.primitive_count = part.line_count;
            vertices.assign(model.lines.begin() + 2 * part.first_line,
                            model.lines.begin() + 2 * (part.first_line + part.line_count));
            if (transfer)
                records_of(transfer->lines, 2 * std::size_t(part.first_line),
                           2 * std::size_t(part.line_count));
        }
        scale_vertices(vertices, scale);
        if (part.primitive == lod_primitive::lines)  // the same vertices, drawn as splats
            e.mesh_splats = add_sample_mesh(
                assets, primitive_mesh(vertices, primitive_kind::points, part.material, records),
                2 * e.primitive_count);
        const primitive_kind kind =
            part.primitive == lod_primitive::points ? primitive_kind::points : primitive_kind::lines;
        e.mesh_primitives = add_sample_mesh(
            assets, primitive_mesh(std::move(vertices), kind, part.material, std::move(records)),
            e.primitive_count);
        assets.library.lod_parts.push_back(e);
    }
    return first;
}

}  // namespace

void add_point_line_parts(scene_assets& assets, species_entry& entry, const point_line_model& model,
                          float scale, float importance, const point_line_records* transfer) {
    if (model.cells.empty()) return;
    // The triangles' records ride on a copy of their mesh, so extract_triangles carries them.
    point_line_model with_transfer_storage;
    const point_line_model* with_transfer = &model;
    if (transfer) {
        if (transfer->triangles.size() != model.triangles.vertices.size() ||
            transfer->points.size() != model.points.size() ||
            transfer->lines.size() != model.lines.size())
            throw std::logic_error(
                "add_point_line_parts: transfer records must match the model's vertices");
        with_transfer_storage.triangles = model.triangles;
        with_transfer_storage.triangles.transfer = transfer->triangles;
        with_transfer = &with_transfer_storage;
    }
    entry.first_cell = std::uint32_t(assets.library.cells.size());
    entry.cell_count = std::uint32_t(model.cells.size());
    for (const lod_cell& cell : model.cells) {
        const std::uint32_t first =
            add_cell_parts(assets, model, cell, scale, importance, *with_transfer, transfer);
        assets.library.cells.push_back({first, cell.part_count});
    }
    // One cell: the plant itself carries its parts' prefixes. Several (§6.1): its cells do.
    if (model.cells.size() == 1) {
        entry.first_lod_part = assets.library.cells.back().first_lod_part;
        entry.lod_part_count = assets.library.cells.back().lod_part_count;
    }
}

}  // namespace sylva
