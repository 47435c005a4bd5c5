// Generation time of the plant library (issue 3: a 200,000-triangle tree in at most 1 s on one
// core). Triangles per generated mesh are reported as counters.
#include <benchmark/benchmark.h>

#include <string>

#include "models/generate/plant_library.h"
#include "models/generate/tree_generator.h"

namespace {

void time_full_tree(benchmark::State& state, const sylva::tree_params& params) {
    std::size_t triangles = 0;
    std::uint64_t seed = 0;
    for (auto _ : state) {
        const sylva::mesh_data mesh = sylva::generate_tree(params, ++seed, sylva::tree_detail::full);
        triangles = mesh.triangle_count();
        benchmark::DoNotOptimize(mesh.vertices.data());
    }
    state.counters["triangles"] = double(triangles);
}

void bm_broadleaf_hd_full(benchmark::State& state) { time_full_tree(state, sylva::tree_preset("broadleaf_hd")); }
BENCHMARK(bm_broadleaf_hd_full)->Unit(benchmark::kMillisecond);

// The figure at its size: broadleaf_hd with half again as many leaves per twig and
// rounder stems, about 200,000 triangles.
void bm_broadleaf_200k_full(benchmark::State& state) {
    sylva::tree_params params = sylva::tree_preset("broadleaf_hd");
    params.leaves_per_stem = params.leaves_per_stem * 3 / 2;
    for (auto& level : params.level) level.sides += 2;
    time_full_tree(state, params);
}
BENCHMARK(bm_broadleaf_200k_full)->Unit(benchmark::kMillisecond);

// The whole model: three lods and both textures at 512 x 512.
void bm_plant_model(benchmark::State& state, std::string preset) {
    std::array<std::size_t, 3> triangles{};
    std::uint64_t seed = 0;
    for (auto _ : state) {
        const sylva::plant_model model = sylva::generate_plant_model(preset, ++seed, 512);
        for (std::size_t i = 0; i < 3; ++i) triangles[i] = model.lods[i].triangle_count();
        benchmark::DoNotOptimize(model.leaf_texture.texels.data());
    }
    state.counters["tris_full"] = double(triangles[0]);
    state.counters["tris_reduced"] = double(triangles[1]);
    state.counters["tris_far"] = double(triangles[2]);
}

const bool k_registered = [] {
    for (const std::string_view preset : sylva::k_plant_presets)
        benchmark::RegisterBenchmark(("bm_plant_model/" + std::string(preset)).c_str(), bm_plant_model, std::string(preset))
            ->Unit(benchmark::kMillisecond);
    return true;
}();

}  // namespace

BENCHMARK_MAIN();
