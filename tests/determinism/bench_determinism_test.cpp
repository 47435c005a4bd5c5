// `sylva bench` measures: apart from timings, the same numbers for any thread count (issue 4,
// item 5), the reference compared with itself gives zero error, and representation switches
// are seen where there are some and not where there are none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "../gl/gl_test_support.h"
#include "app/bench_runner.h"
#include "scenarios/scenario_loader.h"
#include "tests/tiny_scene.h"

namespace sylva {
namespace {

std::vector<bench_configuration_spec> some_configurations() {
    std::vector<bench_configuration_spec> chosen;
    for (const auto& c : default_bench_configurations())
        if (c.name == "reference" || c.name == "brute_force" || c.name == "mesh_lod" ||
            c.name == "baseline" || c.name == "points_lines_d2" || c.name == "billboard_clouds" ||
            c.name == "billboard_clouds_sh")
            chosen.push_back(c);
    return chosen;
}

bench_report bench_tiny(int threads) {
    scenario s = testing::tiny_with_mesh_levels();
    bench_settings settings;
    settings.threads = threads;
    settings.costs = primitive_costs{1.0, 0.5, 4.0};  // fixed: a measurement would differ run to run
    return run_bench(s, some_configurations(), *testing::shared_gl_context(), nullptr, settings);
}

const bench_configuration& named(const bench_report& r, const std::string& name) {
    for (const auto& c : r.configurations)
        if (c.name == name) return c;
    throw std::runtime_error("no configuration " + name);
}

TEST(bench_determinism, errors_and_primitives_are_identical_for_1_and_2_threads) {
    SYLVA_REQUIRE_GL();
    const bench_report one = bench_tiny(1);
    const bench_report two = bench_tiny(2);
    ASSERT_EQ(one.configurations.size(), 7u);
    ASSERT_EQ(two.configurations.size(), 7u);
    for (std::size_t i = 0; i < one.configurations.size(); ++i) {
        const bench_configuration& a = one.configurations[i];
        const bench_configuration& b = two.configurations[i];
        SCOPED_TRACE(a.name);
        // Bit-identical, not approximately equal: the images and IDs they come from are.
        EXPECT_EQ(a.error.rmse, b.error.rmse);
        EXPECT_EQ(a.error.ssim, b.error.ssim);
        EXPECT_EQ(a.error.perceptual, b.error.perceptual);
        EXPECT_EQ(a.error.coverage_iou, b.error.coverage_iou);
        EXPECT_EQ(a.error.popping, b.error.popping);
        EXPECT_TRUE(a.error.lighting_jump == b.error.lighting_jump ||
                    (std::isnan(a.error.lighting_jump) && std::isnan(b.error.lighting_jump)));
        EXPECT_EQ(a.error.transitions, b.error.transitions);
        EXPECT_EQ(a.error.transitions_by_kind, b.error.transitions_by_kind);
        EXPECT_EQ(a.primitives, b.primitives);
        EXPECT_EQ(a.upload_bytes, b.upload_bytes);
    }

    const bench_error& self = named(one, "reference").error;
    EXPECT_TRUE(std::isinf(self.psnr_db));
    EXPECT_EQ(self.rmse, 0.0);
    EXPECT_EQ(self.ssim, 1.0);
    EXPECT_EQ(self.perceptual, 0.0);
    EXPECT_EQ(self.coverage_iou, 1.0);
    EXPECT_EQ(self.popping, 0.0);

    // Brute force never switches: no transition, and a lighting jump of n/a, not 0. The
    // baseline's hard switch does along tiny's camera path, and its billboards differ from the
    // reference.
    EXPECT_EQ(named(one, "brute_force").error.transitions, 0u);
    EXPECT_TRUE(std::isnan(named(one, "brute_force").error.lighting_jump));
    EXPECT_TRUE(std::isnan(self.lighting_jump));
    EXPECT_GT(named(one, "baseline").error.transitions, 0u);
    EXPECT_EQ(named(one, "baseline").error.transitions_by_kind.at("switch"),
              named(one, "baseline").error.transitions);
    EXPECT_GT(named(one, "baseline").error.lighting_jump, 0.0);
    EXPECT_GT(named(one, "brute_force").error.rmse, 0.0);  // one sample per pixel aliases
    EXPECT_GT(named(one, "brute_force").primitives.at("triangles"),
              named(one, "mesh_lod").primitives.at("triangles"));
    // The point/line representation draws points and lines, and fewer triangles than brute force.
    EXPECT_GT(named(one, "points_lines_d2").primitives.at("points"), 0.0);
    EXPECT_GT(named(one, "points_lines_d2").primitives.at("lines"), 0.0);
    EXPECT_LT(named(one, "points_lines_d2").primitives.at("triangles"),
              named(one, "brute_force").primitives.at("triangles"));
    EXPECT_EQ(one.primitive_costs.at("point"), 0.5);
    EXPECT_EQ(named(one, "points_lines_d2").primitive_costs.at("line"), 4.0);
    EXPECT_TRUE(named(one, "baseline").primitive_costs.empty());
    // Billboard clouds (Behrendt 2005 §2.3) are drawn along tiny's path, with their fades.
    EXPECT_GT(named(one, "billboard_clouds").primitives.at("instances_billboard_cloud"), 0.0);
}

// bench_settings::timing_rounds: the later rounds time every configuration again, alternating
// the order round by round, and change no error; the time against the baseline is the median
// of the round-by-round ratios.
TEST(bench_timing_rounds, later_rounds_time_every_configuration_and_change_no_error) {
    SYLVA_REQUIRE_GL();
    scenario s = testing::tiny_with_mesh_levels();
    s.frames = 3;
    std::vector<bench_configuration_spec> chosen;
    for (const auto& c : default_bench_configurations())
        if (c.name == "reference" || c.name == "baseline" || c.name == "points_lines_d2")
            chosen.push_back(c);
    bench_settings settings;
    settings.costs = primitive_costs{1.0, 0.5, 4.0};
    const bench_report once =
        run_bench(s, chosen, *testing::shared_gl_context(), nullptr, settings);

    std::vector<std::pair<std::uint32_t, int>> round_starts;  // (round, configuration) at frame 0
    settings.timing_rounds = 3;
    settings.progress = [&](const bench_progress& p) {
        EXPECT_EQ(p.rounds, 3u);
        if (p.frame == 0 && p.configuration >= 0)
            round_starts.emplace_back(p.round, p.configuration);
    };
    const bench_report thrice =
        run_bench(s, chosen, *testing::shared_gl_context(), nullptr, settings);
    EXPECT_EQ(thrice.timing_rounds, 3u);
    // Round 0 in order, round 1 backwards, round 2 forwards again; the reference (0) only in
    // round 0.
    const std::vector<std::pair<std::uint32_t, int>> expected = {{0, 0}, {0, 1}, {0, 2}, {1, 2},
                                                                 {1, 1}, {2, 1}, {2, 2}};
    EXPECT_EQ(round_starts, expected);

    ASSERT_EQ(thrice.configurations.size(), 3u);
    EXPECT_EQ(named(thrice, "reference").frame_ms_rounds.size(), 1u);
    EXPECT_TRUE(
        std::isnan(named(thrice, "reference").frame_ms_vs_baseline));  // one round: no ratio
    const bench_configuration& baseline = named(thrice, "baseline");
    const bench_configuration& points = named(thrice, "points_lines_d2");
    for (const bench_configuration* c : {&baseline, &points}) {
        SCOPED_TRACE(c->name);
        ASSERT_EQ(c->frame_ms_rounds.size(), 3u);
        for (const double round_median : c->frame_ms_rounds) {
            EXPECT_GT(round_median, 0.0);
            EXPECT_LE(c->frame_ms_min, round_median);
            EXPECT_GE(c->frame_ms_max, round_median);
        }
        EXPECT_LE(c->frame_ms_min, c->frame_ms_median);
        EXPECT_GE(c->frame_ms_max, c->frame_ms_median);
        const bench_configuration& alone = named(once, c->name);
        EXPECT_EQ(alone.frame_ms_rounds.size(), 1u);
        EXPECT_EQ(c->error.rmse, alone.error.rmse);
        EXPECT_EQ(c->error.ssim, alone.error.ssim);
        EXPECT_EQ(c->error.popping, alone.error.popping);
        EXPECT_EQ(c->primitives, alone.primitives);
    }
    EXPECT_EQ(baseline.frame_ms_vs_baseline, 1.0);
    std::vector<double> ratios;
    for (std::size_t r = 0; r < 3; ++r)
        ratios.push_back(points.frame_ms_rounds[r] / baseline.frame_ms_rounds[r]);
    std::sort(ratios.begin(), ratios.end());
    EXPECT_EQ(points.frame_ms_vs_baseline, ratios[1]);
}

}  // namespace
}  // namespace sylva
