// The device calibration of shader work (systems/render/shader_work_calibration.h) through the
// real renderer: the invocations it counts are the shapes it draws, its fit reproduces every
// sample from its counts, and it refuses a timer that sees no work.
#include <gtest/gtest.h>

#include <filesystem>

#include "gl_test_support.h"
#include "scenarios/scenario_loader.h"
#include "setup/spawn_scenario.h"
#include "systems/render/shader_work_calibration.h"

namespace sylva {
namespace {

render::calibration_settings quick(render::frame_timer timer) {
    render::calibration_settings s;
    s.first_count = 2000;
    s.max_count = 8000;
    s.min_marginal_ms = 1.0;
    s.min_repetitions = 3;
    s.max_repetitions = 3;
    s.timer = std::move(timer);
    return s;
}

struct shadowed_renderer {
    scene_assets assets = build_scene_assets(
        load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "scenarios/tiny.json"), nullptr);
    std::unique_ptr<render::renderer> r = [this] {
        render::renderer_settings settings;
        settings.width = 320;
        settings.height = 180;
        settings.shadows = true;
        settings.shadow_resolution = 512;
        return std::make_unique<render::renderer>(settings, assets);
    }();
};

// A made-up device: 7 ms a frame, and per triangle 1 µs small, 2 µs large, 4 µs into the shadow map.
double made_up_ms(const render::calibration_frame& f) {
    constexpr double k_us[] = {1.0, 2.0, 4.0};
    return 7.0 + 1e-3 * double(f.count) * k_us[f.shape];
}

TEST(shader_work_calibration, counts_the_shapes_it_draws_and_fits_every_sample) {
    SYLVA_REQUIRE_GL();
    shadowed_renderer s;
    const render::work_calibration_result result =
        render::calibrate_shader_work(*s.r, quick([](const render::calibration_frame& f, const auto& draw) {
            draw();
            return made_up_ms(f);
        }));
    ASSERT_TRUE(result.costs) << result.refusal;
    ASSERT_EQ(result.samples.size(), 3u);
    const work_sample &small = result.samples[0], &large = result.samples[1], &shadow = result.samples[2];
    // 2,000 more unindexed triangles: 3 vertices each, in every shape.
    EXPECT_EQ(small.vertices, 6000.0);
    EXPECT_EQ(large.vertices, 6000.0);
    EXPECT_EQ(shadow.vertices, 6000.0);
    // Legs of 4 and 24 px: 8 and 288 px of area; the large shade far more fragments.
    EXPECT_GT(large.fragments, 10.0 * small.fragments);
    EXPECT_GT(small.fragments, 2000.0 * 4.0);
    EXPECT_EQ(shadow.fragments, 0.0) << "the shadow shape draws nothing in the view";
    EXPECT_GT(shadow.shadow_fragments, 0.0);
    EXPECT_EQ(small.shadow_fragments, 0.0);
    // Three samples, three coefficients: the fit reproduces each sample's time (2, 4 and 8 ms).
    for (const work_sample& w : result.samples)
        EXPECT_NEAR(result.costs->cost_us(w.vertices, w.fragments, 0.0, w.shadow_fragments), w.us, 1e-6 * w.us);
    EXPECT_NEAR(small.us, 2000.0, 1e-6);
    EXPECT_NEAR(shadow.us, 8000.0, 1e-6);
}

TEST(shader_work_calibration, refuses_a_timer_that_sees_no_work) {
    SYLVA_REQUIRE_GL();
    shadowed_renderer s;
    const render::work_calibration_result constant =
        render::calibrate_shader_work(*s.r, quick([](const render::calibration_frame&, const auto& draw) {
            draw();
            return 16.0;
        }));
    EXPECT_FALSE(constant.costs);
    EXPECT_NE(constant.refusal.find("not above the timer's noise"), std::string::npos) << constant.refusal;
}

}  // namespace
}  // namespace sylva
