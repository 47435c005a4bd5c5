// STYLE habit 5: once warm, the frame loop allocates nothing. A scenario is played through its
// camera path once (every buffer the loop keeps then holds its largest frame), then the same
// frames again while every operator new in the process is counted (tests/allocation_counter.h:
// what it sees and what it cannot). The count must be 0: the systems on the worker threads, the
// draw-list build, the submission (programs, commands, uniforms, passes) and the player's
// per-frame record into a reused frame_record.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

#include "app/scenario_player.h"
#include "models/cache/bake_cache.h"
#include "scenarios/scenario_loader.h"
#include "systems/render/gl_context.h"
#include "tests/allocation_counter.h"

namespace sylva {
namespace {

struct loop_case {
    const char* scenario;
    const char* representation;
    const char* lighting;
    const char* splats;
    bool id_buffer;
};

std::string case_name(const ::testing::TestParamInfo<loop_case>& info) {
    const loop_case& c = info.param;
    return std::string(c.scenario) + "_" + c.representation + "_" + c.lighting + "_" + c.splats +
           (c.id_buffer ? "_ids" : "");
}

class warm_frame_allocations : public ::testing::TestWithParam<loop_case> {};

TEST_P(warm_frame_allocations, the_second_pass_over_the_camera_path_allocates_nothing) {
    const loop_case& c = GetParam();
    scenario s = load_bundled_scenario(c.scenario);
    s.width = 160;
    s.height = 90;
    s.frames = 4;
    s.lod.representation = c.representation;
    s.lod.plant_budget_ms = 0.0;  // "ladder": by projected size, though default ships a budget
    // "auto": the ladder with rungs chosen by the budget solver (resources/rung_budget.h).
    if (s.lod.representation == "auto") {
        s.lod.representation = "ladder";
        s.lod.plant_budget_ms = 60.0;
    }
    s.lod.lighting = c.lighting;
    for (species_settings& species : s.species) species.lighting = "scenario";
    s.lod.splats = c.splats;
    std::unique_ptr<render::gl_context> context;
    try {
        render::context_options options;
        options.width = int(s.width);
        options.height = int(s.height);
        options.headless = true;
        context = render::create_context(options);
    } catch (const std::exception& e) {
        GTEST_SKIP() << "no GL 4.5 context (OSMesa): " << e.what();
    }
    bake_cache cache;  // $SYLVA_CACHE_DIR or the user's: this test is about playback
    player_options options;
    options.id_buffer = c.id_buffer;
    scenario_player player(s, 2, context.get(), &cache, options);

    frame_record record;
    for (std::uint64_t f = 0; f < s.frames; ++f) player.step(record);
    player.set_frame(0);
    testing::counting_allocations counter;
    for (std::uint64_t f = 0; f < s.frames; ++f) player.step(record);
    const testing::allocation_counts counts = counter.stop();
    std::printf("warm frames: %llu allocations of ours, %llu in the GL driver\n",
                static_cast<unsigned long long>(counts.allocations),
                static_cast<unsigned long long>(counts.driver));
    if (counts.allocations != 0) testing::counting_allocations::print_sites();
    EXPECT_EQ(counts.allocations, 0u) << counts.bytes << " bytes over " << s.frames
                                      << " warm frames; call stacks of the first above";
    EXPECT_GT(record.draw_calls, 0u);  // the frames were drawn
}

INSTANTIATE_TEST_SUITE_P(
    frame_loop, warm_frame_allocations,
    ::testing::Values(loop_case{"tiny", "mesh_levels", "normal_mapped", "soft", false},
                      loop_case{"tiny", "points_lines", "sh", "soft", false},
                      loop_case{"tiny", "points_lines", "normal_mapped", "opaque", true},
                      loop_case{"tiny", "points_lines", "pre_lit", "soft", true},
                      loop_case{"tiny", "billboard_clouds", "pre_lit", "soft", false},
                      loop_case{"tiny", "billboard_clouds", "sh", "soft", true},
                      loop_case{"default", "points_lines", "normal_mapped", "soft", false},
                      // The papers' ladder (points fading in and out as partners), and default's own.
                      loop_case{"tiny", "ladder", "sh", "soft", true},
                      loop_case{"default", "ladder", "normal_mapped", "soft", false},
                      loop_case{"default", "auto", "normal_mapped", "soft", false}),
    case_name);

}  // namespace
}  // namespace sylva
