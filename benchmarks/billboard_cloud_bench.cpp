// Bake time of a billboard cloud (issue 6: at most 10 s for a 200,000-triangle tree on 2
// cores): broadleaf_hd as generated (about 133,000 triangles) and with half again as many
// leaves per twig and rounder stems (about 200,000, as plant_generation_bench builds it), each
// clustered, boxed and rendered into its atlas with the default settings. Triangles, clusters
// and billboards are reported as counters.
#include <benchmark/benchmark.h>

#include "models/bake/billboard_cloud.h"
#include "models/generate/plant_library.h"
#include "models/generate/tree_generator.h"

namespace {

void time_cloud(benchmark::State& state, bool enlarged) {
    sylva::plant_model model = sylva::generate_plant_model("broadleaf_hd", 1, 256);
    if (enlarged) {
        sylva::tree_params params = sylva::tree_preset("broadleaf_hd");
        params.leaves_per_stem = params.leaves_per_stem * 3 / 2;
        for (auto& level : params.level) level.sides += 2;
        model.lods[0] = sylva::generate_tree(params, 1, sylva::tree_detail::full);
    }
    const sylva::billboard_cloud_settings settings = sylva::default_billboard_cloud_settings(model);
    std::size_t clusters = 0, billboards = 0;
    for (auto _ : state) {
        const sylva::billboard_cloud cloud = sylva::bake_billboard_cloud(model, settings);
        clusters = cloud.clusters.size();
        billboards = cloud.billboards.size();
        benchmark::DoNotOptimize(cloud.pages[0].texels.data());
    }
    state.counters["triangles"] = double(model.lods[0].triangle_count());
    state.counters["clusters"] = double(clusters);
    state.counters["billboards"] = double(billboards);
}

void bm_cloud_broadleaf_hd(benchmark::State& state) { time_cloud(state, false); }
BENCHMARK(bm_cloud_broadleaf_hd)->Unit(benchmark::kMillisecond)->Iterations(3);

void bm_cloud_broadleaf_200k(benchmark::State& state) { time_cloud(state, true); }
BENCHMARK(bm_cloud_broadleaf_200k)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
