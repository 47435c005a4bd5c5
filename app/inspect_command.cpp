// `sylva inspect`: what the importer makes of a glTF plant, level by level.
#include <spdlog/spdlog.h>

#include <cstdio>
#include <string>

#include "app/commands.h"
#include "models/gltf/gltf_import.h"
#include "models/gltf/gltf_plant_builder.h"

namespace sylva {
namespace {

struct inspect_options {
    std::string file;
    std::uint32_t texture_size = 256;
};

struct level_counts {
    std::uint32_t bark_triangles = 0;
    std::uint32_t leaf_triangles = 0;
    std::uint32_t leaves = 0;  // connected leaf pieces: cards, sprays, blades
};

level_counts count(const mesh_data& mesh) {
    level_counts c;
    std::vector<std::uint32_t> leaf_indices;
    for (const submesh& s : mesh.submeshes) {
        if (s.material == material_kind::leaf) {
            c.leaf_triangles += s.index_count / 3;
            leaf_indices.insert(leaf_indices.end(), mesh.indices.begin() + s.first_index,
                                mesh.indices.begin() + s.first_index + s.index_count);
        } else {
            c.bark_triangles += s.index_count / 3;
        }
    }
    triangle_components(mesh.vertices, leaf_indices, c.leaves);
    return c;
}

void print_report(const std::string& file, const gltf_import_result& r) {
    const plant_model& m = r.model;
    std::printf("%s\n", file.c_str());
    std::printf("units: %s (source unit scale %g, converted to metres)\n",
                m.source_unit_scale == 1.0f ? "metres" : "centimetres",
                double(m.source_unit_scale));
    if (m.has_hierarchy)
        std::printf("branches: %u mesh nodes, nested %u deep\n", r.mesh_nodes, r.hierarchy_depth);
    else
        std::printf("branches: none (no branch hierarchy in the nodes; geometry-only)\n");
    std::printf("materials: %zu\n", r.materials.size());
    for (const std::string& name : r.materials)
        std::printf("  %s\n", name.empty() ? "(unnamed)" : name.c_str());
    std::printf("primitives: %zu\n", r.primitives.size());
    for (const auto& p : r.primitives)
        std::printf(
            "  %-32s %-5s material '%s', %u triangles, %u pieces (largest %.0f %%), alpha cut %.0f "
            "%%%s\n",
            p.label.c_str(), p.leaf ? "leaf" : "bark", p.material.c_str(), p.triangles,
            p.components, 100.0 * double(p.largest_component_share), 100.0 * double(p.alpha_ratio),
            p.green ? ", green" : "");
    std::printf("%-8s %10s %10s %10s %8s  %s\n", "lod", "triangles", "bark", "leaf", "leaves",
                "bounds (m)");
    const char* names[3] = {"full", "reduced", "far"};
    for (std::size_t i = 0; i < 3; ++i) {
        const mesh_data& mesh = m.lods[i];
        const level_counts c = count(mesh);
        std::printf("%-8s %10zu %10u %10u %8u  (%.3f, %.3f, %.3f) .. (%.3f, %.3f, %.3f)\n",
                    names[i], mesh.triangle_count(), c.bark_triangles, c.leaf_triangles, c.leaves,
                    double(mesh.bounds_min.x), double(mesh.bounds_min.y), double(mesh.bounds_min.z),
                    double(mesh.bounds_max.x), double(mesh.bounds_max.y),
                    double(mesh.bounds_max.z));
    }
    for (const std::string& w : r.warnings) std::printf("warning: %s\n", w.c_str());
}

int inspect(const inspect_options& o) {
    gltf_import_result result;
    try {
        result = import_gltf_plant(o.file, o.texture_size);
    } catch (const std::exception& e) {
        // Every importer error is about the file: bad input.
        spdlog::error("{}", e.what());
        return k_exit_bad_input;
    }
    print_report(o.file, result);
    return k_exit_ok;
}

}  // namespace

command_runner add_inspect_command(CLI::App& app) {
    auto options = std::make_shared<inspect_options>();
    app.add_option("file", options->file, "A .gltf or .glb plant")->required();
    app.add_option("--texture-size", options->texture_size, "Texture size the import resamples to")
        ->check(CLI::Range(16u, 4096u))
        ->capture_default_str();
    return [options] { return inspect(*options); };
}

}  // namespace sylva
