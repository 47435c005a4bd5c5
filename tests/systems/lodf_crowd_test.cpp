// Issue 23's ECS cost, as a test: many plants on the LoDF rung (tests/systems/lodf_crowd.h) with
// a moving camera give bit-identical slots and cluster counters for 1, 2 and 4 threads, frame
// by frame, and each frame changes only some of the clusters. Its time: benchmarks/lodf_update_bench.
#include <gtest/gtest.h>

#include "ecs/executor.h"
#include "models/generate/plant_library.h"
#include "tests/systems/lodf_crowd.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_plants = 200;
constexpr std::uint32_t k_frames = 30;

struct walk {
    std::vector<std::uint64_t> hashes;
    std::vector<std::uint32_t> changed;  // clusters changed per frame
};

walk run_walk(int threads, const lodf_model& model, const mesh_data& full) {
    testing::lodf_crowd crowd(k_plants, model, full);
    ecs::executor executor(threads);
    walk w;
    for (std::uint32_t f = 0; f < k_frames; ++f) {
        crowd.place_camera(f);
        executor.run([&] { crowd.schedule.run(crowd.world, executor); });
        w.hashes.push_back(crowd.state_hash());
        w.changed.push_back(crowd.world.resource<lodf_slots>().changed_clusters);
        EXPECT_EQ(crowd.world.resource<lodf_slots>().overflow, 0u) << "a slot per plant";
    }
    return w;
}

TEST(lodf_crowd, cluster_state_is_identical_for_1_2_and_4_threads_and_each_frame_touches_few_clusters) {
    const plant_model plant = generate_plant_model("broadleaf", 3, 64);
    const lodf_model model = bake_lodf(plant.lods[0], plant.has_hierarchy);
    const walk one = run_walk(1, model, plant.lods[0]);
    for (int threads : {2, 4}) EXPECT_EQ(run_walk(threads, model, plant.lods[0]).hashes, one.hashes) << threads << " threads";
    // Every plant on the rung has a slot, and the walk moves detail: after the first frame
    // (every slot taken), each frame changes some clusters but far from all of them.
    const std::uint64_t all = std::uint64_t(k_plants) * model.structure.clusters.size();
    std::uint32_t frames_with_changes = 0;
    for (std::uint32_t f = 1; f < k_frames; ++f) {
        EXPECT_LT(one.changed[f], all / 2) << "frame " << f;
        frames_with_changes += one.changed[f] > 0 ? 1u : 0u;
    }
    EXPECT_GE(frames_with_changes, k_frames - 2) << "the camera moves: detail changes almost every frame";
}

}  // namespace
}  // namespace sylva
