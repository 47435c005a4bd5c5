// Degenerate input (app/stress/stress_checks.h): glTF files with non-finite positions are
// rejected with an error that names the vertex; zero-area triangles are dropped at import, and
// the presets make none.
#include <limits>
#include <string_view>

#include "app/stress/check_support.h"
#include "app/stress/stress_checks.h"
#include "models/generate/plant_library.h"
#include "models/gltf/gltf_export.h"
#include "models/gltf/gltf_import.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;
using stress::row;
using stress::rows;
using stress::text;

std::size_t count_zero_area(const mesh_data& mesh) {
    std::size_t n = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        n += is_zero_area_triangle(mesh.vertices[mesh.indices[t]].position,
                                   mesh.vertices[mesh.indices[t + 1]].position,
                                   mesh.vertices[mesh.indices[t + 2]].position);
    return n;
}

stress_row non_finite_vertex_row(const plant_model& grass, const fs::path& dir, float value,
                                 const std::string& stem, const std::string& token) {
    plant_model bad = grass;
    const std::uint32_t vertex = bad.lods[0].indices[4];  // used by the second triangle
    bad.lods[0].vertices[vertex].position.y = value;
    const fs::path file = dir / (stem + ".glb");
    export_plant_glb(bad, plant_lod::full, file);
    const std::string error = stress::error_from([&] { import_gltf_plant(file, 32); });
    const std::string expected = stem + ".glb: mesh 'grass' primitive 0: vertex " +
                                 std::to_string(vertex) + " has a non-finite position (";
    const bool named =
        error.find(expected) != std::string::npos && error.find(token) != std::string::npos;
    return stress::yes_no_row("glTF vertex y = " + token + ": rejected, named", named, "rejected",
                              error.empty() ? "imported" : "rejected, unnamed",
                              "error names file, mesh, vertex, " + token,
                              error.empty() ? "the model imported without an error" : error);
}

// Appends two repeated-index triangles and one of three collinear vertices (binary fractions,
// so collinear in float too) to the last sub-mesh; returns how many it added.
std::uint32_t add_zero_area_triangles(mesh_data& mesh) {
    const auto first = std::uint32_t(mesh.vertices.size());
    const glm::vec3 p{0.25f, 0.5f, -0.125f}, d{0.125f, 0.25f, 0.0625f};
    for (const glm::vec3 q : {p, p + d, p + 2.0f * d})
        mesh.vertices.push_back({q, glm::vec3(0.0f, 1.0f, 0.0f), glm::vec2(0.0f)});
    const std::uint32_t a = mesh.indices[0], b = mesh.indices[1];
    mesh.indices.insert(mesh.indices.end(), {a, a, b, a, b, b, first, first + 1, first + 2});
    mesh.submeshes.back().index_count += 9;
    mesh.parts.resize(mesh.triangle_count(),
                      mesh.parts.empty() ? triangle_part{} : mesh.parts.back());
    return 3;
}

}  // namespace

rows check_degenerate_models(const fs::path& scratch_dir) {
    fs::create_directories(scratch_dir);
    plant_model grass = generate_plant_model("grass", 1, 32);
    grass.name = "grass";
    const float inf = std::numeric_limits<float>::infinity();
    rows out;
    out.push_back(non_finite_vertex_row(grass, scratch_dir, std::numeric_limits<float>::quiet_NaN(),
                                        "nan_vertex", "nan"));
    out.push_back(non_finite_vertex_row(grass, scratch_dir, inf, "plus_inf_vertex", "+inf"));
    out.push_back(non_finite_vertex_row(grass, scratch_dir, -inf, "minus_inf_vertex", "-inf"));

    plant_model slivers = grass;
    const std::uint32_t added = add_zero_area_triangles(slivers.lods[0]);
    export_plant_glb(slivers, plant_lod::full, scratch_dir / "zero_area.glb");
    const gltf_import_result imported = import_gltf_plant(scratch_dir / "zero_area.glb", 32);
    std::size_t left = 0;
    for (const mesh_data& level : imported.model.lods) left += count_zero_area(level);
    const bool kept_real =
        imported.model.lods[0].triangle_count() == grass.lods[0].triangle_count();
    out.push_back(
        row("glTF zero-area triangles: dropped",
            text("%u of %u dropped, %zu left", imported.dropped_degenerate_triangles, added, left),
            double(imported.dropped_degenerate_triangles), "all dropped, none left",
            imported.dropped_degenerate_triangles == added && left == 0 && kept_real,
            kept_real ? "" : "the real triangles were not all kept"));

    for (const std::string_view preset : k_plant_presets) {
        const plant_model m = generate_plant_model(preset, 1, 16);
        std::size_t triangles = 0, zero = 0;
        for (const mesh_data& level : m.lods)
            triangles += level.triangle_count(), zero += count_zero_area(level);
        out.push_back(row("preset " + std::string(preset) + ": zero-area triangles",
                          text("%zu of %zu", zero, triangles), double(zero), "0",
                          zero == 0 && triangles > 0));
    }
    return out;
}

}  // namespace sylva
