// The physical model of primitive costs (lod/primitive_cost_model.h): which path and how many
// pixels each primitive has at a d', the fit per path, and the refusals, on hand-made samples.
#include "lod/primitive_cost_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace sylva {
namespace {

point_line_quality at(float d, splat_style style = splat_style::soft) {
    return {d, 1.3f, true, style, false};
}

TEST(primitive_cost_model, each_primitive_has_its_path_and_pixels_at_a_sample_distance) {
    // Soft splats: S = 2·d'·√1.3; S² = 4·1.3·d'² = 5.2 d'². At d' = 1, S = 2.28 px < 4: drawn
    // directly; at d' = 2, S = 4.56 px: into the half-size layer.
    EXPECT_EQ(splat_path(at(1.0f)), cost_path::soft_splats);
    EXPECT_NEAR(splat_pixels(at(1.0f)), 5.2, 1e-5);
    EXPECT_EQ(splat_path(at(2.0f)), cost_path::layered_soft_splats);
    EXPECT_NEAR(splat_pixels(at(2.0f)), 20.8, 1e-4);
    // Opaque splats: s = d'·√1.3, s² = 1.3 d'², one path at any size.
    EXPECT_EQ(splat_path(at(4.0f, splat_style::opaque)), cost_path::opaque_splats);
    EXPECT_NEAR(splat_pixels(at(4.0f, splat_style::opaque)), 20.8, 1e-4);
    // Lines: one pixel wide up to 1.25 px, then d' wide; 4 px long.
    EXPECT_EQ(line_path(at(1.25f)), cost_path::native_lines);
    EXPECT_DOUBLE_EQ(line_pixels(at(1.0f)), 4.0);
    EXPECT_EQ(line_path(at(1.5f)), cost_path::wide_lines);
    EXPECT_DOUBLE_EQ(line_pixels(at(2.0f)), 8.0);
    EXPECT_DOUBLE_EQ(triangle_pixels(), 8.0);  // legs of 4 px
}

// Samples exactly on t = a + b·pixels for each planned path.
std::vector<cost_sample> exact_samples(const std::array<cost_line, k_cost_paths>& truth) {
    std::vector<cost_sample> samples;
    for (const calibration_point& p : calibration_plan(1.3f)) {
        const double pixels =
            p.path == cost_path::triangles ? triangle_pixels()
            : (p.path == cost_path::native_lines || p.path == cost_path::wide_lines)
                ? line_pixels(p.quality)
                : splat_pixels(p.quality);
        samples.push_back({p.path, pixels, truth[std::size_t(p.path)].at(pixels), 0.001});
    }
    return samples;
}

std::array<cost_line, k_cost_paths> truth() {
    std::array<cost_line, k_cost_paths> t{};
    t[std::size_t(cost_path::triangles)] = {0.6, 0.05};  // 0.6 + 0.05·8 = 1.0 µs a triangle
    t[std::size_t(cost_path::opaque_splats)] = {0.4, 0.01};
    t[std::size_t(cost_path::soft_splats)] = {0.7, 0.02};
    t[std::size_t(cost_path::layered_soft_splats)] = {0.6, 0.003};
    t[std::size_t(cost_path::native_lines)] = {1.0, 0.0};
    t[std::size_t(cost_path::wide_lines)] = {1.5, 0.025};
    return t;
}

TEST(primitive_cost_model, the_fit_recovers_each_paths_line_and_gives_costs_per_triangle) {
    const primitive_cost_model m = fit_cost_model(exact_samples(truth()), 1.3f);
    // Paths measured at two sizes: their lines. Triangles and native lines have one size: their
    // cost there (b = 0, a the cost).
    for (const cost_path p : {cost_path::opaque_splats, cost_path::soft_splats,
                              cost_path::layered_soft_splats, cost_path::wide_lines}) {
        EXPECT_NEAR(m.paths[std::size_t(p)].a_us, truth()[std::size_t(p)].a_us, 1e-9)
            << cost_path_name(p);
        EXPECT_NEAR(m.paths[std::size_t(p)].b_us_per_px, truth()[std::size_t(p)].b_us_per_px, 1e-9)
            << cost_path_name(p);
    }
    EXPECT_NEAR(m.paths[std::size_t(cost_path::triangles)].at(8.0), 1.0, 1e-12);
    EXPECT_NEAR(m.paths[std::size_t(cost_path::native_lines)].at(4.0), 1.0, 1e-12);
    // d' = 1, soft: 0.7 + 0.02·5.2 = 0.804 µs a splat against 1.0 a triangle; native lines 1.0.
    primitive_costs c = m.costs_for(at(1.0f));
    EXPECT_DOUBLE_EQ(c.triangle, 1.0);
    EXPECT_NEAR(c.point, 0.804, 1e-7);  // pixels come from float splat sizes
    EXPECT_NEAR(c.line, 1.0, 1e-9);
    // d' = 3, soft (layered): 0.6 + 0.003·46.8 = 0.7404; wide lines 1.5 + 0.025·12 = 1.8.
    c = m.costs_for(at(3.0f));
    EXPECT_NEAR(c.point, 0.7404, 1e-7);
    EXPECT_NEAR(c.line, 1.8, 1e-9);
    // Within a path the costs grow smoothly with d': never a jump from one d' to the next.
    EXPECT_LT(m.costs_for(at(3.0f)).point, m.costs_for(at(4.0f)).point);
    EXPECT_LT(m.costs_for(at(3.0f)).line, m.costs_for(at(4.0f)).line);
}

TEST(primitive_cost_model, a_cost_falling_with_size_is_noise_and_no_setup_cost_is_negative) {
    std::vector<cost_sample> s = exact_samples(truth());
    // Opaque splats: 0.5 µs at 1.3 px, 0.4 at 20.8 px (falling): the mean, 0.45, for every size.
    for (cost_sample& x : s)
        if (x.path == cost_path::opaque_splats) x.us = x.pixels < 2.0 ? 0.5 : 0.4;
    // Wide lines: 0.1 µs at 8 px and 1.0 at 32 px: the line through them crosses zero at 5.33 px;
    // through the origin instead, b = Σxy / Σx² = (0.8 + 32) / (64 + 1024) = 0.030147.
    for (cost_sample& x : s)
        if (x.path == cost_path::wide_lines) x.us = x.pixels < 10.0 ? 0.1 : 1.0;
    const primitive_cost_model m = fit_cost_model(s, 1.3f);
    EXPECT_DOUBLE_EQ(m.paths[std::size_t(cost_path::opaque_splats)].b_us_per_px, 0.0);
    EXPECT_NEAR(m.paths[std::size_t(cost_path::opaque_splats)].a_us, 0.45, 1e-12);
    EXPECT_DOUBLE_EQ(m.paths[std::size_t(cost_path::wide_lines)].a_us, 0.0);
    EXPECT_NEAR(m.paths[std::size_t(cost_path::wide_lines)].b_us_per_px, 32.8 / 1088.0, 1e-12);
}

TEST(primitive_cost_model, refuses_what_it_cannot_trust_and_says_which_path) {
    auto refusal = [](const std::vector<cost_sample>& s) {
        try {
            fit_cost_model(s, 1.3f);
        } catch (const calibration_refused& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    std::vector<cost_sample> s = exact_samples(truth());
    // Below five standard errors: 1.0 ± 0.21 µs.
    s[0].error_us = 0.21;
    EXPECT_NE(refusal(s).find("triangles at 8 px"), std::string::npos) << refusal(s);
    s[0].error_us = 0.19;
    EXPECT_EQ(refusal(s), "");
    // Zero, negative or not a number.
    for (const double bad : {0.0, -0.5, std::nan("")}) {
        std::vector<cost_sample> t = exact_samples(truth());
        t[3].us = bad;
        EXPECT_NE(refusal(t).find("not above the timer's noise"), std::string::npos) << bad;
    }
    // A path of the plan not measured at all.
    std::vector<cost_sample> missing;
    for (const cost_sample& x : exact_samples(truth()))
        if (x.path != cost_path::native_lines) missing.push_back(x);
    EXPECT_NE(refusal(missing).find("no measurement of native lines"), std::string::npos)
        << refusal(missing);
    // A line 300 times a triangle is a broken timer, not a device.
    std::vector<cost_sample> absurd = exact_samples(truth());
    for (cost_sample& x : absurd)
        if (x.path == cost_path::native_lines) x.us = 300.0;
    EXPECT_NE(refusal(absurd).find("broken timer"), std::string::npos) << refusal(absurd);
}

}  // namespace
}  // namespace sylva
