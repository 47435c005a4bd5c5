// The device calibration of primitive costs (issue 5, item 6): it measures something for every
// kind, and its rounded ratios are what the selection uses.
#include "systems/render/primitive_cost_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "gl_test_support.h"
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

}  // namespace
}  // namespace sylva
