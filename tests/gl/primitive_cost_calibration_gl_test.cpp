// The device calibration of primitive costs (issue 5 item 6, issue 18 item 3) through the real
// renderer: its bookkeeping recovers a known cost exactly from a timer that reports it, it refuses
// a timer that reports garbage, it gets a model out of this device, and it leaves no trace in the
// frames after it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "app/scenario_player.h"
#include "calibration_test_support.h"
#include "gl_test_support.h"
#include "models/cache/bake_cache.h"
#include "models/random.h"
#include "scenarios/scenario_loader.h"
#include "setup/spawn_scenario.h"
#include "systems/render/primitive_cost_calibration.h"
#include "tests/tiny_scene.h"

namespace sylva {
namespace {

std::unique_ptr<render::renderer> small_renderer(const scene_assets& assets) {
    render::renderer_settings settings;
    settings.width = 320;
    settings.height = 180;
    settings.shadows = false;
    return std::make_unique<render::renderer>(settings, assets);
}

scene_assets tiny_assets() {
    return build_scene_assets(testing::tiny_with_mesh_levels(), nullptr);
}

using testing::quick_calibration;

// What a frame of `f` costs in a made-up device: 7 ms of its own, plus per primitive
// 0.5 + 0.02·pixels µs (soft splats), 1 + 0.01·pixels (triangles), 0.3 + 0.05·pixels (the rest).
double made_up_ms(const render::calibration_frame& f) {
    double a = 0.3, b = 0.05, pixels = 0.0;
    switch (f.path) {
        case cost_path::triangles:
            a = 1.0, b = 0.01, pixels = triangle_pixels();
            break;
        case cost_path::soft_splats:
            a = 0.5, b = 0.02, pixels = splat_pixels(f.quality);
            break;
        case cost_path::native_lines:
        case cost_path::wide_lines:
            pixels = line_pixels(f.quality);
            break;
        default:
            pixels = splat_pixels(f.quality);
    }
    return 7.0 + 1e-3 * double(f.count) * (a + b * pixels);
}

TEST(primitive_cost_calibration, recovers_a_known_device_exactly_through_the_renderer) {
    SYLVA_REQUIRE_GL();
    const scene_assets assets = tiny_assets();
    auto r = small_renderer(assets);
    const render::calibration_result result = render::calibrate_primitive_costs(
        *r, quick_calibration([](const render::calibration_frame& f, const auto& draw) {
            draw();
            return made_up_ms(f);
        }));
    ASSERT_TRUE(result.model) << result.refusal;
    const primitive_cost_model& m = *result.model;
    EXPECT_NEAR(m.paths[std::size_t(cost_path::triangles)].a_us +
                    8.0 * m.paths[std::size_t(cost_path::triangles)].b_us_per_px,
                1.08, 1e-9);
    EXPECT_NEAR(m.paths[std::size_t(cost_path::soft_splats)].a_us, 0.5, 1e-9);
    EXPECT_NEAR(m.paths[std::size_t(cost_path::soft_splats)].b_us_per_px, 0.02, 1e-9);
    EXPECT_NEAR(m.paths[std::size_t(cost_path::wide_lines)].b_us_per_px, 0.05, 1e-9);
    // d' = 1, soft: (0.5 + 0.02·5.2) / 1.08 = 0.55926 triangles a splat (pixels from float sizes).
    EXPECT_NEAR(m.costs_for({1.0f, 1.3f, true, splat_style::soft, true}).point, 0.604 / 1.08, 1e-7);
    EXPECT_EQ(result.samples.size(), calibration_plan(1.3f).size());
}

TEST(primitive_cost_calibration, refuses_a_timer_that_reports_noise_or_nothing) {
    SYLVA_REQUIRE_GL();
    const scene_assets assets = tiny_assets();
    auto r = small_renderer(assets);
    rng random(42, 0);
    const render::calibration_result noise = render::calibrate_primitive_costs(
        *r, quick_calibration([&](const render::calibration_frame&, const auto& draw) {
            draw();
            return double(random.uniform(0.0f, 50.0f));
        }));
    EXPECT_FALSE(noise.model);
    EXPECT_NE(noise.refusal, "");
    const render::calibration_result constant = render::calibrate_primitive_costs(
        *r, quick_calibration([](const render::calibration_frame&, const auto& draw) {
            draw();
            return 16.0;
        }));
    EXPECT_FALSE(constant.model);
    EXPECT_NE(constant.refusal.find("not above the timer's noise"), std::string::npos)
        << constant.refusal;
    // A timer that sees the work but whose noise swamps it: each frame N·1 µs·(1 + u), u uniform
    // in [0, 1), so every marginal time c(1 + 2u₂ − u₁) is positive, but its spread is as large
    // as its value: the signal-to-noise rule alone refuses it.
    const render::calibration_result swamped = render::calibrate_primitive_costs(
        *r, quick_calibration([&](const render::calibration_frame& f, const auto& draw) {
            draw();
            return 1e-3 * double(f.count) * (1.0 + double(random.uniform(0.0f, 1.0f)));
        }));
    EXPECT_FALSE(swamped.model);
    EXPECT_NE(swamped.refusal.find("not above the timer's noise"), std::string::npos)
        << swamped.refusal;
}

TEST(primitive_cost_calibration, measures_this_device) {
    SYLVA_REQUIRE_GL();
    const scene_assets assets = tiny_assets();
    auto r = small_renderer(assets);
    render::calibration_settings s;
    s.timer = render::device_frame_timer(testing::shared_gl_context()->renderer());
    s.max_repetitions = 15;  // a quiet machine settles in about 7, a loaded one within 15
    const render::calibration_result result = render::calibrate_primitive_costs(*r, s);
    ASSERT_TRUE(result.model) << result.refusal;
    for (const cost_sample& sample : result.samples)
        std::printf("%-20s %6.2f px %.4f ± %.4f us\n", cost_path_name(sample.path), sample.pixels,
                    sample.us, sample.error_us);
    const primitive_costs c = result.model->costs_for({2.0f, 1.3f, true, splat_style::soft, true});
    EXPECT_GT(c.point, 0.0);
    EXPECT_GT(c.line, 0.0);
}

TEST(primitive_cost_calibration, leaves_no_trace_in_the_frames_after_it) {
    // The calibration draws with its own camera and sky through the scene's renderer; a frame
    // after it must equal the same frame without it (it once left its own sky behind, because
    // both environments carried revision 1).
    SYLVA_REQUIRE_GL();
    const scenario s = testing::tiny_with_mesh_levels();
    const std::filesystem::path dir =
        std::filesystem::path(::testing::TempDir()) / "sylva_calibration_trace";
    std::filesystem::remove_all(dir);
    bake_cache cache(dir);
    player_options options;
    options.policy.mode = lod_policy::kind::points_lines;
    options.policy.points = {2.0f, 1.3f};
    options.measure_costs = true;
    options.calibration = quick_calibration(render::process_cpu_ms);
    scenario_player calibrated(s, 2, testing::shared_gl_context(), &cache, options);
    calibrated.step();
    const image_rgba8 after = calibrated.capture();

    options.measure_costs = false;
    options.costs = calibrated.costs();
    scenario_player plain(s, 2, testing::shared_gl_context(), nullptr, options);
    plain.step();
    const image_rgba8 without = plain.capture();
    ASSERT_EQ(after.texels.size(), without.texels.size());
    EXPECT_TRUE(after.texels == without.texels);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sylva
