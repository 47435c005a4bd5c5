// `sylva export-cloud MODEL --out FILE.glb`: bakes a plant's billboard cloud (Behrendt 2005 §2)
// and writes it as binary glTF with its atlas embedded, printing what the bake produced:
// clusters, billboards, atlas bytes, bake time and how much smaller the minimum-volume boxes are
// than the PCA boxes. MODEL is a species preset or a .gltf/.glb file.
#include <spdlog/spdlog.h>

#include <chrono>
#include <string>

#include "app/commands.h"
#include "app/model_argument.h"
#include "models/bake/billboard_cloud.h"
#include "models/gltf/gltf_export.h"

namespace sylva {
namespace {

struct export_cloud_options {
    std::string model;
    std::string out;
    std::uint32_t clusters = 0;
    std::string method = "auto";
    int level = -1;
    std::uint64_t seed = 1;
    std::uint32_t texture_size = 256;
    std::uint32_t atlas_width = 0;
    std::uint32_t atlas_height = 0;
};

clustering_method method_of(const std::string& name) {
    if (name == "hierarchy") return clustering_method::hierarchy;
    if (name == "kmeans") return clustering_method::kmeans;
    if (name == "geometric") return clustering_method::geometric;
    return clustering_method::automatic;
}

// One line a person and a script can both read.
void report(const std::string& name, const plant_model& model, const billboard_cloud& cloud, double ms) {
    std::size_t by_count[4] = {0, 0, 0, 0};
    std::vector<std::size_t> per_cluster(cloud.clusters.size(), 0);
    for (const cloud_billboard& b : cloud.billboards) ++per_cluster[b.cluster];
    for (std::size_t n : per_cluster) ++by_count[std::min<std::size_t>(n, 3)];
    double min_volume = 0.0, pca_volume = 0.0;
    for (const cloud_cluster& c : cloud.clusters) min_volume += c.box.volume(), pca_volume += c.pca_volume;
    const std::string level = cloud.branching_level >= 0 ? " level " + std::to_string(cloud.branching_level) : "";
    spdlog::info("{}: {} triangles -> {} clusters ({}{}) -> {} billboards (1/2/3 per cluster: {}/{}/{}); "
                 "atlas {} x {}, {} bytes ({} colour + {} normal); min-volume/PCA box volume {:.3f}; bake {:.0f} ms",
                 name, model.lods[0].triangle_count(), cloud.clusters.size(), name_of(cloud.method), level,
                 cloud.billboards.size(), by_count[1], by_count[2], by_count[3], cloud.atlas_width, cloud.atlas_height,
                 cloud.atlas_bytes(), cloud.page(cloud_atlas_page::albedo).texels.size(),
                 cloud.page(cloud_atlas_page::normal).texels.size(), pca_volume > 0.0 ? min_volume / pca_volume : 1.0,
                 ms);
}

int export_cloud(const export_cloud_options& o) {
    if (o.model.empty() || o.out.empty()) {
        spdlog::error("export-cloud: give a MODEL (a preset: {}; or a .gltf/.glb file) and --out FILE.glb",
                      plant_preset_list());
        return k_exit_bad_input;
    }
    plant_model model;
    try {
        model = load_plant_argument(o.model, o.seed, o.texture_size);
    } catch (const std::exception& e) {  // the model cannot be used: bad input
        spdlog::error("export-cloud: {}", e.what());
        return k_exit_bad_input;
    }
    try {
        billboard_cloud_settings settings = default_billboard_cloud_settings(model);
        if (o.clusters) settings.clustering.target_clusters = o.clusters;
        settings.clustering.method = method_of(o.method);
        settings.clustering.branching_level = o.level;
        if (o.atlas_width) settings.atlas_width = o.atlas_width;
        if (o.atlas_height) settings.atlas_height = o.atlas_height;
        const auto start = std::chrono::steady_clock::now();
        const billboard_cloud cloud = bake_billboard_cloud(model, settings);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const std::string name = plant_argument_name(o.model);
        export_billboard_cloud_glb(cloud, name, o.out);
        report(name, model, cloud, ms);
        spdlog::info("wrote {}", o.out);
    } catch (const std::invalid_argument& e) {
        spdlog::error("export-cloud: {}", e.what());
        return k_exit_bad_input;
    } catch (const std::exception& e) {
        spdlog::error("export-cloud: {}", e.what());
        return k_exit_failure;
    }
    return k_exit_ok;
}

}  // namespace

command_runner add_export_cloud_command(CLI::App& app) {
    auto options = std::make_shared<export_cloud_options>();
    app.add_option("model", options->model, "A species preset (see `sylva plant --list`) or a .gltf/.glb plant");
    app.add_option("--out", options->out, "Output file (.glb)");
    app.add_option("--clusters", options->clusters,
                   "Rough number of clusters (default: 60 for plants 4 m and taller, 25 below; each gives 1-3 billboards)")
        ->check(CLI::Range(1u, 5000u));
    app.add_option("--method", options->method,
                   "Clustering: auto (hierarchy when the model has one, else geometric), hierarchy, kmeans, geometric")
        ->check(CLI::IsMember({"auto", "hierarchy", "kmeans", "geometric"}))
        ->capture_default_str();
    app.add_option("--level", options->level,
                   "Hierarchy: the branching level whose sub-branches are the clusters (-1: chosen by --clusters)")
        ->check(CLI::Range(-1, 64))
        ->capture_default_str();
    app.add_option("--seed", options->seed, "Preset seed (the same as `sylva plant`)")->capture_default_str();
    app.add_option("--texture-size", options->texture_size, "Leaf and bark texture size the plant is built with")
        ->check(CLI::Range(16u, 4096u))
        ->capture_default_str();
    app.add_option("--atlas-width", options->atlas_width, "Atlas width in texels (default: 1024 trees, 512 small plants)")
        ->check(CLI::Range(16u, 16384u));
    app.add_option("--atlas-height", options->atlas_height, "Atlas height in texels (default: 512 trees, 256 small plants)")
        ->check(CLI::Range(16u, 16384u));
    return [options] { return export_cloud(*options); };
}

}  // namespace sylva
