// Bake time of a plant's radiance transfer (issue 7: at most 20 s for a 200,000-triangle tree's
// full-mesh vertices at 64 rays each on 2 cores): broadleaf_hd with half again as many leaves
// per twig and rounder stems (about 200,000 triangles, as billboard_cloud_bench builds it), its
// full mesh as occluder and its vertices as receivers, on 1 and 2 threads. The Embree scene is
// built outside the timed loop (its build time is the occluder_seconds counter); vertices,
// triangles and rays per second are counters. Real time, since the work runs on TBB's workers.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <chrono>

#include "models/generate/plant_library.h"
#include "models/bake/radiance_transfer.h"
#include "models/generate/tree_generator.h"

namespace {

sylva::plant_model tree_200k() {
    sylva::plant_model model = sylva::generate_plant_model("broadleaf_hd", 1, 256);
    sylva::tree_params params = sylva::tree_preset("broadleaf_hd");
    params.leaves_per_stem = params.leaves_per_stem * 3 / 2;
    for (auto& level : params.level) level.sides += 2;
    model.lods[0] = sylva::generate_tree(params, 1, sylva::tree_detail::full);
    return model;
}

void bm_transfer_broadleaf_200k(benchmark::State& state) {
    const auto threads = std::size_t(state.range(0));
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    static const sylva::plant_model model = tree_200k();
    const sylva::mesh_data& full = model.lods[0];
    const auto start = std::chrono::steady_clock::now();
    const sylva::transfer_occluders occluders(full, model.leaf_texture, model.bark_texture);
    const std::chrono::duration<double> build = std::chrono::steady_clock::now() - start;
    const sylva::transfer_settings settings;  // 3 bands, 64 rays, no bounce
    for (auto _ : state) {
        const sylva::radiance_transfer t = occluders.bake(full.vertices, settings);
        benchmark::DoNotOptimize(t.front.data());
    }
    const double rays = double(full.vertices.size()) * settings.rays_per_receiver;
    state.counters["threads"] = double(threads);
    state.counters["vertices"] = double(full.vertices.size());
    state.counters["triangles"] = double(full.triangle_count());
    state.counters["occluder_seconds"] = build.count();
    state.counters["rays_per_second"] =
        benchmark::Counter(rays * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(bm_transfer_broadleaf_200k)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
