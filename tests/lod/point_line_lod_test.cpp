// Deussen 2002 §5: Eq. 1, Eq. 2 and the §5.3 blend against values computed by hand.
#include "lod/point_line_lod.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "lighting/fog.h"

namespace sylva {
namespace {

std::vector<std::uint32_t> stratified_after(std::uint32_t k) {
    std::vector<std::uint32_t> after(k + 1);
    for (std::uint32_t t = 0; t <= k; ++t) after[t] = 2 * (k - t);
    return after;
}

TEST(point_line_lod, a_pixel_at_90_degrees_and_500_pixels_is_0_004_on_the_image_plane) {
    // 2 * tan(45°) / 500 = 0.004.
    EXPECT_NEAR(image_plane_units(1.0, std::numbers::pi / 2.0, 500.0), 0.004, 1e-12);
    EXPECT_NEAR(image_plane_units(2.5, std::numbers::pi / 2.0, 500.0), 0.01, 1e-12);
}

TEST(point_line_lod, eq1_projected_area_is_half_the_area_over_r_squared) {
    EXPECT_DOUBLE_EQ(projected_area(8.0, 2.0), 1.0);    // ½ · 8 / 4
    EXPECT_DOUBLE_EQ(projected_area(0.08, 10.0), 4e-4);  // ½ · 0.08 / 100
}

TEST(point_line_lod, eq1_points_cover_the_projected_area_cp_times_with_splats_of_d_squared) {
    // c_p · A'_p / d'² = 1.5 · (½ · 8 / 2²) / 0.01² = 1.5 · 1 / 1e-4 = 15000.
    EXPECT_NEAR(required_points(8.0, 2.0, 0.01, 1.5), 15000.0, 1e-6);
    // ½ · 0.08 / 10² / 0.004² = 4e-4 / 1.6e-5 = 25 with c_p = 1.
    EXPECT_NEAR(required_points(0.08, 10.0, 0.004, 1.0), 25.0, 1e-9);
    // Twice as far: a quarter of the points.
    EXPECT_NEAR(required_points(0.08, 20.0, 0.004, 1.0), 6.25, 1e-9);
    EXPECT_TRUE(std::isinf(required_points(1.0, 0.0, 0.004, 1.0)));
    EXPECT_TRUE(std::isnan(required_points(1.0, std::nan(""), 0.004, 1.0)));
}

TEST(point_line_lod, fog_spaces_samples_by_one_over_the_root_of_the_transmittance) {
    // d' = 0.004 at 1 km in ρ = 0.0009 fog: T = exp(−0.9) = 0.40657, d'/√T = 0.004·exp(0.45)
    // = 0.004·1.568312 = 0.0062732, so Eq. 1 asks for T = 0.40657 of the points.
    EXPECT_NEAR(fog_sample_distance(0.004, 1000.0, 0.0009), 0.0062732, 1e-7);
    EXPECT_NEAR(std::pow(0.004 / fog_sample_distance(0.004, 1000.0, 0.0009), 2.0),
                fog_transmittance(1000.0, 0.0009), 1e-9);
    // At 5 km exp(2.25) = 9.49 is capped at k_fog_sample_growth_max = 4: 0.016.
    EXPECT_NEAR(fog_sample_distance(0.004, 5000.0, 0.0009), 0.016, 1e-12);
    // No fog, no growth.
    EXPECT_EQ(fog_sample_distance(0.004, 1000.0, 0.0), 0.004);
}

TEST(point_line_lod, blend_draws_every_triangle_from_three_points_per_triangle) {
    const auto after = stratified_after(10);
    EXPECT_EQ(blend_points(30.0, 10, after), (part_draw{10, 0}));
    EXPECT_EQ(blend_points(1e9, 10, after), (part_draw{10, 0}));
    EXPECT_EQ(blend_points(std::numeric_limits<double>::infinity(), 10, after), (part_draw{10, 0}));
}

TEST(point_line_lod, blend_between_2k_and_3k_draws_p_minus_2k_triangles_and_the_other_triangles_points) {
    const auto after = stratified_after(10);
    EXPECT_EQ(blend_points(20.0, 10, after), (part_draw{0, 20}));  // p = 2k: every point, no triangle
    EXPECT_EQ(blend_points(25.0, 10, after), (part_draw{5, 10}));  // 5 triangles + 2 · 5 points
    EXPECT_EQ(blend_points(29.5, 10, after), (part_draw{9, 2}));
    // Rendered vertices (points + 3 · triangles) never exceed p + 3 and never 3k.
    for (double p = 20.0; p < 30.0; p += 0.25) {
        const part_draw d = blend_points(p, 10, after);
        EXPECT_LE(d.primitives + 3 * d.triangles, std::uint32_t(p) + 3) << p;
        EXPECT_LE(d.primitives + 3 * d.triangles, 30u) << p;
    }
}

TEST(point_line_lod, blend_below_2k_draws_the_first_p_points) {
    const auto after = stratified_after(10);
    EXPECT_EQ(blend_points(19.9, 10, after), (part_draw{0, 19}));
    EXPECT_EQ(blend_points(6.25, 10, after), (part_draw{0, 6}));
    EXPECT_EQ(blend_points(0.5, 10, after), (part_draw{0, 0}));
    EXPECT_EQ(blend_points(-3.0, 10, after), (part_draw{0, 0}));
    EXPECT_EQ(blend_points(std::nan(""), 10, after), (part_draw{0, 0}));
}

TEST(point_line_lod, blend_with_area_weighted_points_takes_the_remaining_triangles_points_from_the_table) {
    // 4 triangles holding 5, 0, 2, 1 points (8 = 2k in all, spread by area); reverse order.
    const std::vector<std::uint32_t> after{8, 3, 3, 1, 0};
    EXPECT_EQ(blend_points(9.0, 4, after), (part_draw{1, 3}));   // t = 1: points of triangles 1..3
    EXPECT_EQ(blend_points(11.0, 4, after), (part_draw{3, 1}));  // t = 3: triangle 3's one point
    EXPECT_EQ(blend_points(7.0, 4, after), (part_draw{0, 7}));
}

TEST(point_line_lod, measured_costs_move_the_polygon_threshold_to_rho_k) {
    const auto after = stratified_after(10);
    // ρ = 2 (a point costs half a triangle, as on llvmpipe): polygons from p = 2k, no blend.
    const primitive_costs llvmpipe{1.0, 0.5, 4.0};
    EXPECT_EQ(blend_points(19.5, 10, after, llvmpipe), (part_draw{0, 19}));
    EXPECT_EQ(blend_points(20.0, 10, after, llvmpipe), (part_draw{10, 0}));
    // ρ = 1.5: polygons already at p = 15 points (15 points cost as much as 10 triangles).
    const primitive_costs dear_points{3.0, 2.0, 3.0};
    EXPECT_EQ(blend_points(14.0, 10, after, dear_points), (part_draw{0, 14}));
    EXPECT_EQ(blend_points(15.0, 10, after, dear_points), (part_draw{10, 0}));
    // ρ = 8: the blend runs from 2k = 20 to 8k = 80, t = (p − 20) / 6.
    const primitive_costs cheap_points{1.0, 0.125, 1.0};
    EXPECT_EQ(blend_points(35.0, 10, after, cheap_points), (part_draw{2, 16}));  // t = 2.5 → 2
    EXPECT_EQ(blend_points(79.0, 10, after, cheap_points), (part_draw{9, 2}));   // t = 9.83 → 9
    EXPECT_EQ(blend_points(80.0, 10, after, cheap_points), (part_draw{10, 0}));
}

TEST(point_line_lod, lines_dearer_than_their_triangles_are_drawn_as_triangles) {
    // q = 0.9 asks for 9 lines: 9 · 4 = 36 triangles' cost against k = 40 → lines; k = 30 → triangles.
    const primitive_costs llvmpipe{1.0, 0.5, 4.0};
    EXPECT_EQ(select_lines(0.18, 5.0, 0.01, 10, 40, 10.0, 0.004, llvmpipe), (part_draw{0, 9}));
    EXPECT_EQ(select_lines(0.18, 5.0, 0.01, 10, 30, 10.0, 0.004, llvmpipe), (part_draw{30, 0}));
}

TEST(point_line_lod, importance_moves_the_polygon_threshold_not_the_point_count) {
    const auto after = stratified_after(10);
    // m = 4: p = 8 decides as 32 >= 3k → every triangle; p = 6 decides as 24 → 4 triangles and
    // the 12 points of the other 6; p = 4 decides as 16 < 2k → the 4 points coverage needs.
    EXPECT_EQ(blend_points(8.0, 10, after, {}, 4.0), (part_draw{10, 0}));
    EXPECT_EQ(blend_points(6.0, 10, after, {}, 4.0), (part_draw{4, 12}));
    EXPECT_EQ(blend_points(4.0, 10, after, {}, 4.0), (part_draw{0, 4}));
    // Lines: q = 0.36 at r = 25 (4 lines); with m = 3, 3q > 1 → triangles; at r = 50,
    // q = 0.18 and 3q = 0.54 → the 2 lines q asks for.
    EXPECT_EQ(select_lines(0.18, 5.0, 0.01, 10, 40, 25.0, 0.004, {}, 3.0), (part_draw{40, 0}));
    EXPECT_EQ(select_lines(0.18, 5.0, 0.01, 10, 40, 50.0, 0.004, {}, 3.0), (part_draw{0, 2}));
}

TEST(point_line_lod, eq2_lines_are_polygons_when_their_error_is_larger_than_d_prime) {
    // ε_l / r = 0.05 / 20 = 0.0025 >= d' = 0.001: triangles.
    EXPECT_EQ(select_lines(0.2, 5.0, 0.05, 10, 40, 20.0, 0.001), (part_draw{40, 0}));
}

TEST(point_line_lod, eq2_draws_q_times_n_lines_while_q_is_at_most_one) {
    // A_l = 0.18, l = 5, ε_l = 0.01, n_l = 10, d' = 0.004: q = (½·A/r²) / (l·d'/(2r)) = A / (r·l·d').
    EXPECT_EQ(select_lines(0.18, 5.0, 0.01, 10, 40, 5.0, 0.004), (part_draw{40, 0}));  // q = 1.8 > 1
    EXPECT_EQ(select_lines(0.18, 5.0, 0.01, 10, 40, 10.0, 0.004), (part_draw{0, 9}));  // q = 0.9
    EXPECT_EQ(select_lines(0.18, 5.0, 0.01, 10, 40, 25.0, 0.004), (part_draw{0, 4}));  // q = 0.36 → 3.6 → 4
    EXPECT_EQ(select_lines(0.18, 5.0, 0.01, 10, 40, 40.0, 0.004), (part_draw{0, 2}));  // q = 0.225 → 2.25 → 2
    EXPECT_EQ(select_lines(0.18, 5.0, 0.01, 10, 40, 50.0, 0.004), (part_draw{0, 2}));  // q = 0.18 → 1.8 → 2
    // r = 60: a line's image l / (2r·n_l) = 0.0042 is still d' long; q = 0.15 → 1.5 → 2.
    EXPECT_EQ(select_lines(0.18, 5.0, 0.01, 10, 400, 60.0, 0.004), (part_draw{0, 2}));
}

TEST(point_line_lod, lines_shorter_than_d_prime_on_screen_become_splats_at_their_ends) {
    // A_l = 1.8, l = 5 in n_l = 10 lines of 0.5 m, d' = 0.004, c_p = 1.3. At r = 100 a line's
    // image is 5 / (2·100·10) = 0.0025 < d': Eq. 1 on the part, p = 1.3·(½·1.8 / 100²) / 0.004²
    // = 1.3·9e-5 / 1.6e-5 = 7.3125 splats, of 2·n_l = 20 line ends.
    EXPECT_EQ(select_lines(1.8, 5.0, 0.01, 10, 40, 100.0, 0.004), (part_draw{0, 7, true}));  // nearest
    EXPECT_EQ(select_lines(1.8, 5.0, 0.01, 10, 40, 100.0, 0.004, {}, 1.0, 1.3, 0.75), (part_draw{0, 8, true}));
    EXPECT_EQ(select_lines(1.8, 5.0, 0.01, 10, 40, 100.0, 0.004, {}, 1.0, 1.3, 0.0), (part_draw{0, 7, true}));
    // Far away the dither decides whether a part's fraction of a splat is drawn: p = 2.925e-4.
    EXPECT_EQ(select_lines(0.18, 5.0, 0.01, 10, 40, 5000.0, 0.004), (part_draw{0, 0, true}));
    EXPECT_EQ(select_lines(0.18, 5.0, 0.01, 10, 40, 5000.0, 0.004, {}, 1.0, 1.3, 0.9999), (part_draw{0, 1, true}));
    // More splats than line ends (A_l = 6: p = 24.4 > 20) → triangles; splats dearer than the
    // k = 5 triangles (7 points at the paper's 1 against 5·3) are fine, against k = 2 they are not.
    EXPECT_EQ(select_lines(6.0, 5.0, 0.01, 10, 40, 100.0, 0.004), (part_draw{40, 0}));
    EXPECT_EQ(select_lines(1.8, 5.0, 0.01, 10, 5, 100.0, 0.004), (part_draw{0, 7, true}));
    EXPECT_EQ(select_lines(1.8, 5.0, 0.01, 10, 2, 100.0, 0.004), (part_draw{2, 0}));
}

TEST(point_line_lod, sample_dither_is_a_fixed_spread_of_offsets_in_the_unit_interval) {
    double sum = 0.0;
    for (std::uint32_t seed = 0; seed < 4000; ++seed) {
        const double u = sample_dither(seed, seed % 4);
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u;
    }
    EXPECT_NEAR(sum / 4000.0, 0.5, 0.02);  // the mean of U(0, 1); σ of the mean is 0.0046
    EXPECT_EQ(sample_dither(7, 1), sample_dither(7, 1));
    EXPECT_NE(sample_dither(7, 1), sample_dither(7, 2));
}

TEST(point_line_lod, splats_cover_cp_times_d_prime_squared) {
    EXPECT_FLOAT_EQ(splat_size_px({2.0f, 2.25f}), 3.0f);  // 2 · √2.25
    EXPECT_FLOAT_EQ(splat_size_px({1.0f, 1.0f}), 1.0f);
}

// Soft splats (our extension of §5.1): K = 2 times the opaque side, and a Gaussian peak opacity
// that makes each splat deposit the leaf area it stands for, d'²/c_p pixels.
TEST(point_line_lod, soft_splats_are_twice_the_opaque_side_with_area_conserving_opacity) {
    const point_line_quality q{1.0f, 1.3f};
    EXPECT_EQ(q.splats, splat_style::soft);                          // the default
    EXPECT_NEAR(soft_splat_size_px(q), 2.0 * std::sqrt(1.3), 1e-6);  // 2.2804
    // Hand value: 1 / (0.3577763 · 2² · 1.3²) = 1 / 2.418567 = 0.413467.
    EXPECT_NEAR(soft_splat_peak_alpha(q), 0.413467, 1e-5);
    // Independent of d' (S grows with d' as the area does), and never above one.
    EXPECT_NEAR(soft_splat_peak_alpha({3.0f, 1.3f}), 0.413467, 1e-5);
    EXPECT_NEAR(soft_splat_peak_alpha({1.0f, 1.0f}), 1.0 / (0.3577763 * 4.0), 1e-5);  // 0.69876
}

TEST(point_line_lod, the_soft_kernel_mean_is_the_gaussians_mean_over_its_square) {
    // Midpoint rule for (1/2 ∫ exp(-2u²) du over [-1, 1])², against the closed form in the header.
    const int n = 4000;
    double line = 0.0;
    for (int i = 0; i < n; ++i) {
        const double u = -1.0 + 2.0 * (i + 0.5) / n;
        line += std::exp(-2.0 * u * u) / n;
    }
    EXPECT_NEAR(line * line, k_soft_splat_kernel_mean, 1e-6);
}

// As the rasteriser draws a point sprite: the pixels whose centres fall inside the S x S square
// about the splat's centre, each at the Gaussian of its gl_PointCoord. Over random sub-pixel
// positions the opacity a splat deposits averages d'²/c_p, for any d'.
TEST(point_line_lod, a_soft_splat_deposits_the_leaf_area_it_stands_for) {
    for (const float d : {1.0f, 2.0f, 3.5f}) {
        const point_line_quality q{d, 1.3f};
        const double s = soft_splat_size_px(q), peak = soft_splat_peak_alpha(q);
        double total = 0.0;
        const int positions = 64;
        for (int a = 0; a < positions; ++a)
            for (int b = 0; b < positions; ++b) {
                const double cx = 10.0 + (a + 0.5) / positions, cy = 20.0 + (b + 0.5) / positions;
                for (int y = 0; y < 40; ++y)
                    for (int x = 0; x < 40; ++x) {
                        const double u = 2.0 * (x + 0.5 - cx) / s, v = 2.0 * (y + 0.5 - cy) / s;
                        if (std::abs(u) <= 1.0 && std::abs(v) <= 1.0)
                            total += peak * std::exp(-2.0 * (u * u + v * v));
                    }
            }
        EXPECT_NEAR(total / (positions * positions), double(d) * d / 1.3, 0.01 * d * d)
            << "d' = " << d;
    }
}

}  // namespace
}  // namespace sylva
