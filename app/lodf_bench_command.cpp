// `sylva lodf-bench MODEL... [--steps N] [--rounds R] [--json FILE]`: the paper's comparison
// (Rebollo 2006 §5, Figures 10-11) on each model: every level of detail traversed with a
// uniform step, down to the coarsest and back, LoDF's update against re-extracting and
// re-uploading the whole foliage at each change (lod/lodf_traversal.h). Both are timed change by
// change in the same run, so their ratio is fair on a shared machine; medians over the rounds.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/model_argument.h"
#include "io/atomic_file.h"
#include "lod/lodf_traversal.h"

namespace sylva {
namespace {

struct lodf_bench_options {
    std::vector<std::string> models;
    std::uint32_t steps = 100;
    std::uint32_t rounds = 5;
    std::uint64_t seed = 1;
    std::uint32_t texture_size = 64;
    std::string json;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

struct model_result {
    std::string name;
    std::uint32_t leaves = 0, clusters = 0, changes = 0;
    double lodf_bytes = 0.0, whole_bytes = 0.0;  // mean per change
    double lodf_ns = 0.0, whole_ns = 0.0;        // median over rounds of the mean per change
    double time_saved = 0.0;                     // median over rounds of 1 − lodf/whole
    lodf_storage storage;
    std::uint32_t crown_vertices = 0;
    double bake_ms = 0.0;
};

model_result measure(const std::string& argument, const lodf_bench_options& o) {
    const plant_model plant = load_plant_argument(argument, o.seed, o.texture_size);
    const auto start = std::chrono::steady_clock::now();
    const lodf_model model = bake_lodf(plant.lods[0], plant.has_hierarchy);
    model_result r;
    r.bake_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    r.storage = lodf_storage_of(model);
    r.crown_vertices = model.crown_vertices;
    r.name = plant_argument_name(argument);
    r.leaves = model.structure.leaf_count;
    r.clusters = std::uint32_t(model.structure.clusters.size());
    if (r.leaves == 0) throw std::invalid_argument(argument + " has no foliage (no triangles of a leaf material)");
    const std::vector<std::uint32_t> levels = traversal_levels(model.structure, o.steps);
    std::vector<double> lodf_ns, whole_ns, saved;
    for (std::uint32_t round = 0; round < o.rounds; ++round) {
        // The first round also checks that both ways draw the same triangles (untimed).
        const std::vector<traversal_change> changes = traverse_lodf(model, levels, round == 0);
        double l = 0.0, w = 0.0, lb = 0.0, wb = 0.0;
        for (const traversal_change& c : changes) l += c.lodf_ns, w += c.whole_ns, lb += double(c.lodf_bytes), wb += double(c.whole_bytes);
        const auto n = double(changes.size());
        lodf_ns.push_back(l / n);
        whole_ns.push_back(w / n);
        saved.push_back(1.0 - l / w);
        r.lodf_bytes = lb / n, r.whole_bytes = wb / n, r.changes = std::uint32_t(changes.size());
        spdlog::info("{}: round {}/{}", r.name, round + 1, o.rounds);
    }
    r.lodf_ns = median(lodf_ns), r.whole_ns = median(whole_ns), r.time_saved = median(saved);
    return r;
}

int lodf_bench(const lodf_bench_options& o) {
    std::vector<model_result> results;
    for (const std::string& m : o.models) {
        try {
            results.push_back(measure(m, o));
        } catch (const std::invalid_argument& e) {
            spdlog::error("lodf-bench: {}", e.what());
            return k_exit_bad_input;
        } catch (const std::exception& e) {
            spdlog::error("lodf-bench: {}: {}", m, e.what());
            return k_exit_failure;
        }
    }
    std::printf("%-16s %7s %5s %7s | %14s %14s %7s | %12s %12s %7s\n", "model", "leaves", "G", "changes",
                "LoDF B/change", "whole B/change", "fewer", "LoDF us", "whole us", "less");
    nlohmann::ordered_json json = nlohmann::ordered_json::array();
    for (const model_result& r : results) {
        const double fewer = 1.0 - r.lodf_bytes / r.whole_bytes;
        std::printf("%-16s %7u %5u %7u | %14.0f %14.0f %6.1f%% | %12.2f %12.2f %6.1f%%\n", r.name.c_str(), r.leaves,
                    r.clusters, r.changes, r.lodf_bytes, r.whole_bytes, 100.0 * fewer, r.lodf_ns / 1e3,
                    r.whole_ns / 1e3, 100.0 * r.time_saved);
        json.push_back({{"model", r.name},
                        {"leaves", r.leaves},
                        {"clusters", r.clusters},
                        {"changes", r.changes},
                        {"lodf_bytes_per_change", r.lodf_bytes},
                        {"whole_bytes_per_change", r.whole_bytes},
                        {"bytes_fewer", fewer},
                        {"lodf_extraction_us_median", r.lodf_ns / 1e3},
                        {"whole_extraction_us_median", r.whole_ns / 1e3},
                        {"extraction_time_saved_median", r.time_saved},
                        {"crown_vertices", r.crown_vertices},
                        {"storage_words", r.storage.words},
                        {"eq9_words", r.storage.eq9_words},
                        {"stored_bytes", r.storage.bytes},
                        {"bake_ms", r.bake_ms}});
    }
    if (!o.json.empty()) {
        try {
            write_atomically(o.json, nlohmann::ordered_json{{"steps", o.steps}, {"rounds", o.rounds}, {"models", json}}.dump(2) + "\n");
        } catch (const std::exception& e) {
            spdlog::error("lodf-bench: {}", e.what());
            return k_exit_failure;
        }
        spdlog::info("wrote {}", o.json);
    }
    return k_exit_ok;
}

}  // namespace

command_runner add_lodf_bench_command(CLI::App& app) {
    auto options = std::make_shared<lodf_bench_options>();
    app.add_option("models", options->models, "Species presets (see `sylva plant --list`) or .gltf/.glb plants")
        ->required();
    app.add_option("--steps", options->steps,
                   "Uniform steps from the full foliage to the coarsest (and as many back): the paper's step")
        ->check(CLI::Range(1u, 100000u))
        ->capture_default_str();
    app.add_option("--rounds", options->rounds, "Traversals timed; medians over them")
        ->check(CLI::Range(1u, 1000u))
        ->capture_default_str();
    app.add_option("--seed", options->seed, "Preset seed (the same as `sylva plant`)")->capture_default_str();
    app.add_option("--texture-size", options->texture_size, "Texture size the plants are built with (no effect on the result)")
        ->check(CLI::Range(16u, 4096u))
        ->capture_default_str();
    app.add_option("--json", options->json, "Also write the table as JSON to this file");
    return [options] { return lodf_bench(*options); };
}

}  // namespace sylva
