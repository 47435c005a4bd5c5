// Issue 23's ECS cost: 1,000 broadleaf trees on the LoDF rung (Rebollo 2006) with a camera
// walking through them (tests/systems/lodf_crowd.h): the cluster system's time per frame
// (update_lodf: slots, the walk over Changed_group, Eq. 10–13) on 1, 2 and 4 threads, the
// clusters it changes per frame, and a hash of the slots and counters after the walk, which
// must be the same on every thread count. Run: build/bin/lodf_update_bench
#include <benchmark/benchmark.h>

#include <cstdio>

#include "ecs/executor.h"
#include "models/generate/plant_library.h"
#include "tests/systems/lodf_crowd.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_plants = 1000;
constexpr std::uint32_t k_walk_frames = 120;  // one walk; iterations repeat it from frame 0

struct baked_broadleaf {
    plant_model plant = generate_plant_model("broadleaf", 3, 64);
    lodf_model model = bake_lodf(plant.lods[0], plant.has_hierarchy);
};

const baked_broadleaf& broadleaf() {
    static const baked_broadleaf baked;
    return baked;
}

void lodf_update(benchmark::State& state) {
    const baked_broadleaf& b = broadleaf();
    testing::lodf_crowd crowd(k_plants, b.model, b.plant.lods[0]);
    ecs::executor executor(int(state.range(0)));
    std::uint32_t frame = 0;
    std::uint64_t changed = 0;
    std::uint64_t hash_at_walk_end = 0;
    for (auto _ : state) {
        crowd.place_camera(frame);
        executor.run([&] { crowd.schedule.run(crowd.world, executor); });
        changed += crowd.world.resource<lodf_slots>().changed_clusters;
        if (++frame == k_walk_frames) {
            state.PauseTiming();
            if (hash_at_walk_end == 0) hash_at_walk_end = crowd.state_hash();
            frame = 0;
            state.ResumeTiming();
        }
    }
    const lodf_slots& slots = crowd.world.resource<lodf_slots>();
    state.counters["plants_on_rung"] = double(k_plants - slots.overflow);
    state.counters["clusters"] = double(std::size_t(k_plants) * b.model.structure.clusters.size());
    state.counters["leaves_per_plant"] = double(b.model.structure.leaf_count);
    state.counters["changed_clusters_per_frame"] = double(changed) / double(state.iterations());
    // FNV-1a of the state after the walk's last frame (counters are doubles, printed rounded:
    // the label has it whole); "no walk" when the run was too short to finish one.
    char label[32];
    std::snprintf(label, sizeof label, "walk hash %016llx", static_cast<unsigned long long>(hash_at_walk_end));
    state.SetLabel(hash_at_walk_end ? label : "no walk");
}
BENCHMARK(lodf_update)->Arg(1)->Arg(2)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace
}  // namespace sylva

BENCHMARK_MAIN();
