// `sylva export-lodf MODEL --leaves N|P% --out FILE.glb`: bakes a plant's LoDF (Rebollo 2006,
// models/bake/lodf_bake.h) and writes the plant with its foliage at any leaf count as binary glTF,
// trunk and branches included: what the LoDF rung draws at that detail, for any glTF viewer.
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <string>

#include "app/commands.h"
#include "app/model_argument.h"
#include "lod/lodf.h"
#include "models/gltf/gltf_export.h"

namespace sylva {
namespace {

struct export_lodf_options {
    std::string model;
    std::string out;
    std::string leaves = "100%";
    std::uint32_t clusters = 0;
    std::uint64_t seed = 1;
    std::uint32_t texture_size = 256;
};

// "N" leaves, or "P%" of the model's; nothing when the text is neither.
std::optional<std::uint32_t> leaf_count_of(const std::string& text, std::uint32_t model_leaves) {
    try {
        std::size_t used = 0;
        if (!text.empty() && text.back() == '%') {
            const double percent = std::stod(text.substr(0, text.size() - 1), &used);
            if (used + 1 != text.size() || !(percent >= 0.0 && percent <= 100.0)) return std::nullopt;
            return std::uint32_t(std::lround(percent / 100.0 * double(model_leaves)));
        }
        const unsigned long n = std::stoul(text, &used);
        if (used != text.size() || text[0] == '-') return std::nullopt;
        return std::uint32_t(std::min<unsigned long>(n, model_leaves));
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

int export_lodf(const export_lodf_options& o) {
    plant_model plant;
    try {
        plant = load_plant_argument(o.model, o.seed, o.texture_size);
    } catch (const std::exception& e) {  // the model cannot be used: bad input
        spdlog::error("export-lodf: {}", e.what());
        return k_exit_bad_input;
    }
    try {
        const auto start = std::chrono::steady_clock::now();
        const lodf_model lodf = bake_lodf(plant.lods[0], plant.has_hierarchy, {o.clusters});
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const lodf_structure& f = lodf.structure;
        if (f.leaf_count == 0) {
            spdlog::error("export-lodf: {} has no foliage (no triangles of a leaf material) to collapse", o.model);
            return k_exit_bad_input;
        }
        const std::optional<std::uint32_t> wanted = leaf_count_of(o.leaves, f.leaf_count);
        if (!wanted) {
            spdlog::error("export-lodf: --leaves '{}': give a leaf count (0 .. {}) or a percentage (0% .. 100%)",
                          o.leaves, f.leaf_count);
            return k_exit_bad_input;
        }
        const std::uint32_t drawn = f.leaves_after(collapses_for_leaves(f, *wanted));
        if (drawn != *wanted)
            spdlog::warn("export-lodf: {} leaves asked for; LoDF holds {} .. {} (one per cluster at its coarsest), "
                         "so {} are written", *wanted, f.leaf_count - f.collapse_count(), f.leaf_count, drawn);
        plant.lods[0] = lodf_mesh(plant.lods[0], lodf, drawn);
        export_plant_glb(plant, plant_lod::full, o.out);
        spdlog::info("{}: {} leaves in {} clusters, {} written ({:.1f} %), {} triangles; bake {:.0f} ms; wrote {}",
                     plant_argument_name(o.model), f.leaf_count, f.clusters.size(), drawn,
                     100.0 * double(drawn) / double(f.leaf_count), plant.lods[0].triangle_count(), ms, o.out);
    } catch (const std::exception& e) {
        spdlog::error("export-lodf: {}", e.what());
        return k_exit_failure;
    }
    return k_exit_ok;
}

}  // namespace

command_runner add_export_lodf_command(CLI::App& app) {
    auto options = std::make_shared<export_lodf_options>();
    app.add_option("model", options->model, "A species preset (see `sylva plant --list`) or a .gltf/.glb plant")
        ->required();
    app.add_option("--out", options->out, "Output file (.glb)")->required();
    app.add_option("--leaves", options->leaves,
                   "Foliage detail: N leaves, or P% of the model's (LoDF reaches down to one leaf per cluster)")
        ->capture_default_str();
    app.add_option("--clusters", options->clusters,
                   "Clusters G, the leaves of the coarsest level (default: one per 256 leaves)")
        ->check(CLI::Range(1u, 1000000u));
    app.add_option("--seed", options->seed, "Preset seed (the same as `sylva plant`)")->capture_default_str();
    app.add_option("--texture-size", options->texture_size, "Leaf and bark texture size the plant is built with")
        ->check(CLI::Range(16u, 4096u))
        ->capture_default_str();
    return [options] { return export_lodf(*options); };
}

}  // namespace sylva
