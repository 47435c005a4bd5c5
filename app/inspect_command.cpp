// `sylva inspect MODEL`: what Sylva makes of a plant (a glTF file, through the importer, or a
// preset): its mesh levels, and the LoDF structure its foliage bakes into (Rebollo 2006):
// leaves, collapses, clusters and storage against the paper's Eq. 9.
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "app/commands.h"
#include "app/model_argument.h"
#include "models/bake/lodf_bake.h"
#include "models/gltf/gltf_import.h"
#include "models/gltf/gltf_plant_builder.h"

namespace sylva {
namespace {

struct inspect_options {
    std::string file;
    std::uint32_t texture_size = 256;
    std::uint64_t seed = 1;
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

void print_import(const std::string& file, const gltf_import_result& r) {
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
    for (const std::string& w : r.warnings) std::printf("warning: %s\n", w.c_str());
}

void print_levels(const plant_model& m) {
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
}

// Rebollo 2006 §3.2: the structure, and its storage in the paper's words (Eq. 7–8) against Eq. 9.
void print_lodf(const plant_model& m) {
    const auto start = std::chrono::steady_clock::now();
    const lodf_model lodf = bake_lodf(m.lods[0], m.has_hierarchy);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const lodf_structure& f = lodf.structure;
    if (f.leaf_count == 0) {
        std::printf("LoDF: no foliage to collapse\n");
        return;
    }
    std::uint32_t smallest = f.leaf_count, largest = 0;
    for (const lodf_cluster& c : f.clusters)
        smallest = std::min(smallest, c.original_leaves), largest = std::max(largest, c.original_leaves);
    const lodf_storage storage = lodf_storage_of(lodf);
    std::printf("LoDF (Rebollo 2006), baked in %.0f ms:\n", ms);
    std::printf("  leaves L %u (%s), collapses %u, clusters G %u (%u .. %u leaves each), F^r %zu leaves\n",
                f.leaf_count, m.has_hierarchy ? "clustered along the branches" : "clustered along a Morton curve",
                f.collapse_count(), std::uint32_t(f.clusters.size()), smallest, largest, f.nodes.size());
    std::printf("  levels: %u .. %u leaves, any count between; made leaves keep %.0f %% of their pair's area "
                "on average (on existing vertices, Eq. 3)\n",
                f.leaf_count - f.collapse_count(), f.leaf_count, 100.0 * double(lodf.mean_area_ratio));
    std::printf("  storage: %llu words (Eq. 7-8 over the crown's V = %u vertices) against Eq. 9's 6.25 V = %.0f "
                "(%.2f x); %llu bytes as stored\n",
                static_cast<unsigned long long>(storage.words), lodf.crown_vertices, storage.eq9_words,
                double(storage.words) / storage.eq9_words, static_cast<unsigned long long>(storage.bytes));
}

int inspect(const inspect_options& o) {
    plant_model model;
    try {
        if (is_gltf_path(o.file)) {
            const gltf_import_result result = import_gltf_plant(o.file, o.texture_size);
            print_import(o.file, result);
            model = result.model;
        } else {
            model = load_plant_argument(o.file, o.seed, o.texture_size);
            std::printf("%s (preset, seed %llu)\n", o.file.c_str(), static_cast<unsigned long long>(o.seed));
        }
    } catch (const std::exception& e) {
        // Every importer error is about the file: bad input.
        spdlog::error("{}", e.what());
        return k_exit_bad_input;
    }
    print_levels(model);
    print_lodf(model);
    return k_exit_ok;
}

}  // namespace

command_runner add_inspect_command(CLI::App& app) {
    auto options = std::make_shared<inspect_options>();
    app.add_option("model", options->file, "A species preset (see `sylva plant --list`) or a .gltf/.glb plant")
        ->required();
    app.add_option("--seed", options->seed, "Preset seed (the same as `sylva plant`)")->capture_default_str();
    app.add_option("--texture-size", options->texture_size, "Texture size the import resamples to")
        ->check(CLI::Range(16u, 4096u))
        ->capture_default_str();
    return [options] { return inspect(*options); };
}

}  // namespace sylva
