// The device calibration of shader work (systems/render/shader_work_calibration.h) through the
// real renderer: the invocations it counts are the shapes it draws, its fit reproduces every
// sample from its counts, and it refuses a timer that sees no work.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>

#include "calibration_test_support.h"
#include "gl_test_support.h"
#include "scenarios/scenario_loader.h"
#include "setup/spawn_scenario.h"
#include "systems/render/shader_work_calibration.h"
#include "tests/tiny_scene.h"

namespace sylva {
namespace {

using testing::quick_calibration;

struct shadowed_renderer {
    scene_assets assets = build_scene_assets(testing::tiny_with_mesh_levels(), nullptr);
    std::unique_ptr<render::renderer> r = [this] {
        render::renderer_settings settings;
        settings.width = 320;
        settings.height = 180;
        settings.shadows = true;
        settings.shadow_resolution = 512;
        return std::make_unique<render::renderer>(settings, assets);
    }();
};

// A made-up device whose frames cost 7 ms and then exactly c_v = 0.2 µs per vertex, c_f =
// 0.003 per view fragment and c_s = 0.002 per shadow fragment. The timer sees only the shape
// and the count, so a first calibration learns each shape's invocations per triangle (the
// device counts the same every time), and the second times the frames by them.
TEST(shader_work_calibration, counts_the_shapes_it_draws_and_recovers_a_known_device) {
    SYLVA_REQUIRE_GL();
    shadowed_renderer s;
    const render::work_calibration_result counted =
        render::calibrate_shader_work(*s.r, quick_calibration([](const render::calibration_frame& f, const auto& draw) {
            draw();
            return 7.0 + 1e-3 * double(f.count) * (1.0 + double(f.shape));
        }));
    ASSERT_EQ(counted.samples.size(), 4u);
    const work_sample &small = counted.samples[0], &large = counted.samples[1], &shadow = counted.samples[2],
                      &tiny = counted.samples[3];
    // 2,000 more unindexed triangles: 3 vertices each, in every shape.
    for (const work_sample& w : counted.samples) EXPECT_EQ(w.vertices, 6000.0);
    // Legs of 0.4, 4 and 24 px: the large shade far more fragments than the small, the tiny
    // far fewer (most cover no sample).
    EXPECT_GT(large.fragments, 10.0 * small.fragments);
    EXPECT_GT(small.fragments, 2000.0 * 4.0);
    EXPECT_LT(tiny.fragments, small.fragments / 4.0);
    EXPECT_EQ(shadow.fragments, 0.0) << "the shadow shape draws nothing in the view";
    EXPECT_GT(shadow.shadow_fragments, 0.0);
    EXPECT_EQ(small.shadow_fragments, 0.0);

    const shader_work_costs device{0.2, 0.003, 0.002};
    std::array<double, 4> per_triangle_us{};
    for (std::size_t i = 0; i < 4; ++i) {
        const work_sample& w = counted.samples[i];
        per_triangle_us[i] = device.cost_us(w.vertices, w.fragments, 0.0, w.shadow_fragments) / 2000.0;
    }
    const render::work_calibration_result result = render::calibrate_shader_work(
        *s.r, quick_calibration([&](const render::calibration_frame& f, const auto& draw) {
            draw();
            return 7.0 + 1e-3 * double(f.count) * per_triangle_us[f.shape];
        }));
    ASSERT_TRUE(result.costs) << result.refusal;
    EXPECT_NEAR(result.costs->vertex_us, 0.2, 1e-6);
    EXPECT_NEAR(result.costs->fragment_us, 0.003, 1e-9);
    EXPECT_NEAR(result.costs->shadow_fragment_us, 0.002, 1e-9);
}

TEST(shader_work_calibration, refuses_a_timer_that_sees_no_work) {
    SYLVA_REQUIRE_GL();
    shadowed_renderer s;
    const render::work_calibration_result constant =
        render::calibrate_shader_work(*s.r, quick_calibration([](const render::calibration_frame&, const auto& draw) {
            draw();
            return 16.0;
        }));
    EXPECT_FALSE(constant.costs);
    EXPECT_NE(constant.refusal.find("not above the timer's noise"), std::string::npos) << constant.refusal;
}

TEST(shader_work_calibration, refuses_a_renderer_without_shadow_maps_before_timing_anything) {
    SYLVA_REQUIRE_GL();
    const scene_assets assets = build_scene_assets(testing::tiny_with_mesh_levels(), nullptr);
    render::renderer_settings settings;
    settings.width = 320;
    settings.height = 180;
    settings.shadows = false;
    render::renderer r(settings, assets);
    int frames = 0;
    const render::work_calibration_result result =
        render::calibrate_shader_work(r, quick_calibration([&](const render::calibration_frame&, const auto& draw) {
            draw();
            return 16.0 + ++frames;
        }));
    EXPECT_FALSE(result.costs);
    EXPECT_NE(result.refusal.find("no shadow map"), std::string::npos) << result.refusal;
    EXPECT_EQ(frames, 0);
}

}  // namespace
}  // namespace sylva
