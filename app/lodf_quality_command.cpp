// `sylva lodf-quality MODEL... [--leaves 25,50,75]`: LoDF's image quality at equal leaf count
// (issue 23), against the supersampled full plant: LoDF's foliage at P % of the leaves against
// the simple rival every engine can do (a fixed random leaf order drawn as a prefix, survivors
// enlarged to keep the area: lod/leaf_shrink.h), and against the model's own reduced and far
// mesh levels at their leaf counts. Each plant is seen alone from three sides at two sizes
// (app/one_plant_view.h); FLIP and SSIM over the box the plant covers, and the coverage IoU of
// the plant's pixels.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/model_argument.h"
#include "app/one_plant_view.h"
#include "app/scenario_player.h"
#include "io/atomic_file.h"
#include "lod/leaf_shrink.h"
#include "lod/lodf.h"
#include "measure/image_metrics.h"
#include "measure/temporal_metrics.h"
#include "models/bake/lodf_leaves.h"
#include "models/cache/bake_cache.h"
#include "models/image/image_ops.h"
#include "scenarios/scenario_loader.h"
#include "systems/render/gl_context.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_view_px = 256;
constexpr std::array<float, 2> k_sizes_px{240.0f, 96.0f};
constexpr std::array<float, 3> k_azimuths{0.0f, 120.0f, 240.0f};
constexpr std::uint64_t k_rival_seed = 7;

struct lodf_quality_options {
    std::vector<std::string> models;
    std::string leaves = "25,50,75";
    std::uint64_t seed = 1;
    std::uint32_t leaves_per_cluster = k_lodf_leaves_per_cluster;
    std::string json;
};

struct quality {
    double flip = 0.0, ssim = 0.0, iou = 0.0;
};

struct view {
    image_rgba8 image;
    std::vector<std::uint8_t> mask;
};

// The plant's box in either mask, two pixels wider, as x0 y0 x1 y1 (exclusive).
std::array<std::uint32_t, 4> plant_box(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                                       std::uint32_t width, std::uint32_t height) {
    std::array<std::uint32_t, 4> box{width, height, 0, 0};
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x)
            if (a[y * width + x] || b[y * width + x])
                box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x + 1), std::max(box[3], y + 1)};
    if (box[2] == 0) return {0, 0, width, height};
    return {box[0] > 2 ? box[0] - 2 : 0, box[1] > 2 ? box[1] - 2 : 0, std::min(width, box[2] + 2),
            std::min(height, box[3] + 2)};
}

image_rgba8 crop(const image_rgba8& image, const std::array<std::uint32_t, 4>& box) {
    image_rgba8 out;
    out.width = box[2] - box[0];
    out.height = box[3] - box[1];
    out.texels.resize(std::size_t(out.width) * out.height * 4);
    for (std::uint32_t y = 0; y < out.height; ++y)
        std::copy_n(&image.texels[(std::size_t(box[1] + y) * image.width + box[0]) * 4], std::size_t(out.width) * 4,
                    &out.texels[std::size_t(y) * out.width * 4]);
    return out;
}

quality compare(const view& reference, const view& test) {
    const auto box = plant_box(reference.mask, test.mask, k_view_px, k_view_px);
    const image_rgba8 a = crop(reference.image, box), b = crop(test.image, box);
    const double pixels_per_degree = double(k_view_px) / double(k_one_plant_fov_deg);
    return {flip_error(a, b, pixels_per_degree), mean_ssim(a, b), coverage_iou(reference.mask, test.mask)};
}

// The plant drawn with `full_mesh` replaced by `mesh`, from every view; `samples` per pixel side.
std::vector<view> render_views(const scenario& one, const scene_assets& base, const mesh_data& mesh,
                               render::gl_context& context, std::uint32_t samples) {
    scenario s = one;
    s.width = s.height = k_view_px * samples;
    player_options options(geometry_mode::full);
    options.policy = {lod_policy::kind::single, representation::mesh_full, representation::mesh_full, 0.0f};
    options.scenario_lod = false;
    options.measure_costs = false;
    options.id_buffer = true;
    auto assets = std::make_shared<scene_assets>(base);
    assets->meshes[assets->library.species[0].mesh_full] = mesh;
    options.assets = std::move(assets);
    scenario_player player(s, 0, &context, nullptr, options);
    std::vector<view> out;
    for (const float size : k_sizes_px)
        for (const float azimuth : k_azimuths) {
            aim_at_plant(player, size, azimuth, k_view_px, -1.0);  // the same camera at any sampling
            (void)player.step();
            out.push_back({box_downsample(player.capture(), samples), plant_mask(player.capture_plant_ids(samples))});
        }
    return out;
}

// Means over the views of each size.
std::array<quality, k_sizes_px.size()> judge(const std::vector<view>& reference, const std::vector<view>& test) {
    std::array<quality, k_sizes_px.size()> out{};
    for (std::size_t v = 0; v < reference.size(); ++v) {
        const quality q = compare(reference[v], test[v]);
        quality& sum = out[v / k_azimuths.size()];
        sum.flip += q.flip / double(k_azimuths.size());
        sum.ssim += q.ssim / double(k_azimuths.size());
        sum.iou += q.iou / double(k_azimuths.size());
    }
    return out;
}

std::vector<float> percentages_of(const std::string& text) {
    std::vector<float> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        std::size_t used = 0;
        const float p = std::stof(item, &used);
        if (used != item.size() || !(p > 0.0f && p <= 100.0f)) throw std::invalid_argument("--leaves '" + text + "': give percentages in (0, 100], comma-separated");
        out.push_back(p);
    }
    if (out.empty()) throw std::invalid_argument("--leaves is empty");
    return out;
}

void print_row(const std::string& model, const std::string& what, std::uint32_t leaves, std::size_t size,
               const quality& lodf, const std::string& rival_name, const quality& rival, nlohmann::ordered_json& json) {
    const bool lodf_better = lodf.flip < rival.flip && lodf.ssim > rival.ssim && lodf.iou > rival.iou;
    std::printf("%-14s %-10s %7u %5.0f | %7.4f %7.4f %7.4f | %-13s %7.4f %7.4f %7.4f | %s\n", model.c_str(), what.c_str(),
                leaves, double(k_sizes_px[size]), lodf.flip, lodf.ssim, lodf.iou, rival_name.c_str(), rival.flip,
                rival.ssim, rival.iou, lodf_better ? "LoDF better on all three" : "not on all three");
    json.push_back({{"model", model}, {"level", what}, {"leaves", leaves}, {"size_px", k_sizes_px[size]},
                    {"lodf", {{"flip", lodf.flip}, {"ssim", lodf.ssim}, {"iou", lodf.iou}}},
                    {"rival", rival_name},
                    {"rival_quality", {{"flip", rival.flip}, {"ssim", rival.ssim}, {"iou", rival.iou}}},
                    {"lodf_better_on_all_three", lodf_better}});
}

int lodf_quality(const lodf_quality_options& o) {
    std::vector<float> percentages;
    try {
        percentages = percentages_of(o.leaves);
    } catch (const std::exception& e) {
        spdlog::error("lodf-quality: {}", e.what());
        return k_exit_bad_input;
    }
    render::context_options context_options;
    context_options.width = k_view_px;
    context_options.height = k_view_px;
    context_options.headless = true;
    std::unique_ptr<render::gl_context> context;
    try {
        context = render::create_context(context_options);
    } catch (const std::exception& e) {
        spdlog::error("lodf-quality: no GL context: {}", e.what());
        return k_exit_failure;
    }
    bake_cache cache;
    nlohmann::ordered_json json = nlohmann::ordered_json::array();
    std::printf("%-14s %-10s %7s %5s | %7s %7s %7s | %-13s %7s %7s %7s |\n", "model", "level", "leaves", "px", "FLIP",
                "SSIM", "IoU", "against", "FLIP", "SSIM", "IoU");
    for (const std::string& argument : o.models) {
        scenario s = load_default_scenario();
        species_settings species;
        species.name = plant_argument_name(argument);
        if (is_gltf_path(argument)) species.model = std::filesystem::absolute(argument).string();
        else species.generator = argument;
        s.species = {species};
        s.seed = o.seed;
        const scenario one = species_alone(s, 0, k_view_px, "lodf_quality");
        scene_assets base;
        try {
            check_plant_argument(argument);
            player_options options(geometry_mode::full);
            base = build_player_assets(one, options, &cache);
        } catch (const std::exception& e) {
            spdlog::error("lodf-quality: {}", e.what());
            return k_exit_bad_input;
        }
        const species_entry& entry = base.library.species[0];
        const mesh_data full = base.meshes[entry.mesh_full];
        lodf_settings settings;
        settings.leaves_per_cluster = o.leaves_per_cluster;
        const lodf_model lodf = bake_lodf(full, true, settings);
        const std::uint32_t total = lodf.structure.leaf_count;
        if (total == 0) {
            spdlog::error("lodf-quality: {} has no foliage", argument);
            return k_exit_bad_input;
        }
        spdlog::info("{}: {} leaves; rendering the reference", species.name, total);
        const std::vector<view> reference = render_views(one, base, full, *context, k_one_plant_reference_samples);
        const auto lodf_at = [&](std::uint32_t leaves) { return lodf_mesh(full, lodf, leaves); };
        for (const float p : percentages) {
            const auto leaves = std::max<std::uint32_t>(1, std::uint32_t(double(total) * double(p) / 100.0 + 0.5));
            const auto l = judge(reference, render_views(one, base, lodf_at(leaves), *context, 1));
            const auto r = judge(reference, render_views(one, base, leaf_shrink_mesh(full, leaves, k_rival_seed), *context, 1));
            for (std::size_t size = 0; size < k_sizes_px.size(); ++size)
                print_row(species.name, std::to_string(int(p)) + " %", leaves, size, l[size], "leaf shrink", r[size], json);
        }
        for (const auto& [name, mesh] : {std::pair{"reduced", entry.mesh_reduced}, std::pair{"far", entry.mesh_far}}) {
            const mesh_data& level = base.meshes[mesh];
            const auto leaves = std::uint32_t(find_foliage_leaves(level).size());
            const auto l = judge(reference, render_views(one, base, lodf_at(leaves), *context, 1));
            const auto m = judge(reference, render_views(one, base, level, *context, 1));
            for (std::size_t size = 0; size < k_sizes_px.size(); ++size)
                print_row(species.name, std::string("mesh_") + name, leaves, size, l[size], std::string("mesh_") + name, m[size], json);
        }
    }
    if (!o.json.empty()) {
        try {
            write_atomically(o.json, json.dump(2) + "\n");
        } catch (const std::exception& e) {
            spdlog::error("lodf-quality: {}", e.what());
            return k_exit_failure;
        }
        spdlog::info("wrote {}", o.json);
    }
    return k_exit_ok;
}

}  // namespace

command_runner add_lodf_quality_command(CLI::App& app) {
    auto options = std::make_shared<lodf_quality_options>();
    app.add_option("models", options->models, "Species presets (see `sylva plant --list`) or .gltf/.glb plants")
        ->required();
    app.add_option("--leaves", options->leaves, "Leaf counts to compare at, as percentages of the model's")
        ->capture_default_str();
    app.add_option("--seed", options->seed, "Preset seed (the same as `sylva plant`)")->capture_default_str();
    app.add_option("--leaves-per-cluster", options->leaves_per_cluster, "LoDF clusters: one per this many leaves")
        ->check(CLI::Range(2u, 1000000u))
        ->capture_default_str();
    app.add_option("--json", options->json, "Also write the rows as JSON to this file");
    return [options] { return lodf_quality(*options); };
}

}  // namespace sylva
