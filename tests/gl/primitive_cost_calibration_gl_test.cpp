// The device calibration of primitive costs (issue 5, item 6): it measures something for every
// kind, and its rounded ratios are what the selection uses.
#include "systems/render/primitive_cost_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "app/scenario_player.h"
#include "gl_test_support.h"
#include "models/bake_cache.h"
#include "scenarios/scenario_loader.h"
#include "systems/spawn_scenario.h"

namespace sylva {
namespace {

TEST(primitive_cost_calibration, ratios_are_rounded_to_quarters_within_bounds) {
    EXPECT_EQ(render::quantize_cost_ratio(2.1), 2.0);
    EXPECT_EQ(render::quantize_cost_ratio(2.13), 2.25);
    EXPECT_EQ(render::quantize_cost_ratio(0.01), 0.25);
    EXPECT_EQ(render::quantize_cost_ratio(1e9), 64.0);
    EXPECT_EQ(render::quantize_cost_ratio(std::nan("")), 1.0);
    EXPECT_EQ(render::quantize_cost_ratio(-2.0), 1.0);
}

TEST(primitive_cost_calibration, measures_positive_costs_for_triangles_points_and_lines) {
    SYLVA_REQUIRE_GL();
    scenario s = load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "scenarios/tiny.json");
    const scene_assets assets = build_scene_assets(s, nullptr);
    render::renderer_settings settings;
    settings.width = 320;
    settings.height = 180;
    settings.shadows = false;
    render::renderer r(settings, assets);
    render::calibration_settings calibration;
    calibration.primitives = 20000;
    calibration.repetitions = 3;
    calibration.sample_distance_px = 2.0f;
    const render::calibration_result result = render::calibrate_primitive_costs(r, calibration);
    EXPECT_GT(result.triangle_ms_per_million, 0.0);
    EXPECT_GT(result.point_ms_per_million, 0.0);
    EXPECT_GT(result.line_ms_per_million, 0.0);
    EXPECT_EQ(result.costs.triangle, 1.0);
    const double rho = 1.0 / result.costs.point;
    EXPECT_EQ(rho, render::quantize_cost_ratio(rho));
    EXPECT_GE(result.costs.line, 0.25);
    EXPECT_LE(result.costs.line, 64.0);
    std::printf("calibration: %.1f ms per million triangles, %.1f points, %.1f lines -> costs 1 : %.3f : %.2f\n",
                result.triangle_ms_per_million, result.point_ms_per_million, result.line_ms_per_million,
                result.costs.point, result.costs.line);
}

TEST(primitive_cost_calibration, leaves_no_trace_in_the_frames_after_it) {
    // The calibration draws with its own camera and sky through the scene's renderer; a frame
    // after it must equal the same frame without it (it once left its own sky behind, because
    // both environments carried revision 1).
    SYLVA_REQUIRE_GL();
    const scenario s = load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "scenarios/tiny.json");
    const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "sylva_calibration_trace";
    std::filesystem::remove_all(dir);
    bake_cache cache(dir);
    player_options options;
    options.policy.mode = lod_policy::kind::points_lines;
    options.policy.points = {2.0f, 1.3f};
    options.measure_costs = true;
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
