// The same scenario must give bit-identical images and component state for any thread count
// (fixed chunking, registration-ordered conflicts, stable sorts: STYLE.md habit 3).
#include <gtest/gtest.h>

#include <filesystem>

#include "../gl/gl_test_support.h"
#include "app/scenario_player.h"
#include "scenarios/scenario_loader.h"
#include "tests/tiny_scene.h"

namespace sylva {
namespace {

struct run_hashes {
    std::vector<std::uint64_t> image;
    std::vector<std::uint64_t> state;
};

scenario tiny() {
    return testing::tiny_with_mesh_levels();
}

run_hashes play(int threads, render::gl_context* context) {
    scenario_player player(tiny(), threads, context);
    run_hashes hashes;
    for (std::uint32_t f = 0; f < player.settings().frames; ++f) {
        const frame_record r = player.step();
        hashes.state.push_back(r.state_hash);
        if (context) {
            const image_rgba8 image = player.capture();
            hashes.image.push_back(fnv1a(image.texels.data(), image.texels.size()));
        }
    }
    return hashes;
}

TEST(determinism, component_state_is_identical_for_1_2_and_4_threads) {
    const run_hashes one = play(1, nullptr);
    ASSERT_FALSE(one.state.empty());
    for (int threads : {2, 4}) EXPECT_EQ(play(threads, nullptr).state, one.state) << threads << " threads";
}

TEST(determinism, images_and_state_are_identical_for_1_2_and_4_threads) {
    SYLVA_REQUIRE_GL();
    const scenario s = tiny();
    render::context_options options;
    options.width = int(s.width);
    options.height = int(s.height);
    auto context = render::create_context(options);
    const run_hashes one = play(1, context.get());
    for (int threads : {2, 4}) {
        const run_hashes other = play(threads, context.get());
        EXPECT_EQ(other.state, one.state) << threads << " threads";
        EXPECT_EQ(other.image, one.image) << threads << " threads";
    }
}

TEST(determinism, consecutive_frames_differ_so_the_hashes_can_catch_a_change) {
    const run_hashes one = play(2, nullptr);
    ASSERT_GE(one.state.size(), 2u);
    EXPECT_NE(one.state.front(), one.state.back());
}

}  // namespace
}  // namespace sylva
