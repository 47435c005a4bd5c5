#include "lighting/spherical_harmonics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>

namespace sylva {
namespace {

constexpr float k_pi = std::numbers::pi_v<float>;
constexpr int k_theta = 64;
constexpr int k_phi = 128;

const glm::vec3 k_up{0.0f, 1.0f, 0.0f};

std::vector<glm::vec3> probe_directions() {
    return {k_up,
            {0.0f, -1.0f, 0.0f},
            {1.0f, 0.0f, 0.0f},
            {0.0f, 0.0f, -1.0f},
            glm::normalize(glm::vec3(1.0f, 2.0f, 3.0f)),
            glm::normalize(glm::vec3(-0.3f, -0.5f, 0.8f))};
}

float clamped_cosine_about_up(glm::vec3 w) {
    return std::max(0.0f, w.y);
}

TEST(sh_basis, matches_sloans_constants_straight_up) {
    // Y at (0, 1, 0): x = z = 0, y = 1 (table in spherical_harmonics.h).
    const sh9 y = sh_basis(k_up);
    const sh9 expected = {0.282095f, 0.488603f,  0.0f, 0.0f,      0.0f,
                          0.0f,      -0.315392f, 0.0f, -0.546274f};
    for (std::size_t i = 0; i < 9; ++i) EXPECT_FLOAT_EQ(y[i], expected[i]) << i;
}

TEST(sh_basis, is_orthonormal_under_numerical_integration) {
    // Projecting Y_j must give the unit vector e_j: integral Y_i Y_j = delta_ij.
    for (std::size_t j = 0; j < 9; ++j) {
        const sh9_rgb c = project_radiance(
            [j](glm::vec3 w) { return glm::vec3(sh_basis(w)[j], 0.0f, 0.0f); }, k_theta, k_phi);
        for (std::size_t i = 0; i < 9; ++i) {
            EXPECT_NEAR(c.c[i].x, i == j ? 1.0f : 0.0f, 1e-3f) << "i=" << i << " j=" << j;
        }
    }
}

TEST(project_radiance, constant_radiance_lands_in_band_zero_only) {
    // c0 = integral of 1 * Y0 = 4 pi / (2 sqrt(pi)) = 2 sqrt(pi).
    const sh9_rgb c = project_radiance([](glm::vec3) { return glm::vec3(1.0f); }, k_theta, k_phi);
    EXPECT_NEAR(c.c[0].x, 3.544908f, 1e-3f);
    EXPECT_NEAR(c.c[0].z, 3.544908f, 1e-3f);
    // The midpoint rule in theta is second order: 64 rings leave ~1e-3 in the y^2 terms.
    for (std::size_t i = 1; i < 9; ++i) EXPECT_NEAR(c.c[i].y, 0.0f, 1e-3f) << i;
}

TEST(project_radiance, is_deterministic) {
    const auto f = [](glm::vec3 w) { return glm::vec3(w.x * w.x, std::exp(w.y), 1.0f + w.z); };
    const sh9_rgb a = project_radiance(f, 16, 32);
    const sh9_rgb b = project_radiance(f, 16, 32);
    for (std::size_t i = 0; i < 9; ++i) EXPECT_EQ(a.c[i], b.c[i]);
}

TEST(irradiance_from_radiance, constant_unit_radiance_gives_pi_everywhere) {
    // E(n) = integral over the hemisphere of 1 * cos = pi; band 0 is exact.
    const sh9_rgb e = irradiance_from_radiance(
        project_radiance([](glm::vec3) { return glm::vec3(1.0f); }, k_theta, k_phi));
    for (glm::vec3 n : probe_directions()) EXPECT_NEAR(evaluate(e, n).y, k_pi, 2e-3f);
}

TEST(project_radiance, clamped_cosine_lobe_about_up_matches_hand_values) {
    // L(w) = max(0, w.y). Legendre expansion of max(0, t): a0 = 1/4, a1 = 1/2, a2 = 5/16.
    //   c0 = Y0 * pi = sqrt(pi)/2;   c1 (the y term) = 0.488603 * 2 pi / 3 = sqrt(pi/3).
    //   Band 2 is (5/32)(3y^2 - 1) = (5/32)(-(3z^2 - 1)/2 - 3(x^2 - y^2)/2) in this table's
    //   functions, so c6 = -sqrt(5 pi)/16 and c8 = -sqrt(15 pi)/16; every other term is 0.
    const sh9_rgb c = project_radiance(
        [](glm::vec3 w) { return glm::vec3(clamped_cosine_about_up(w)); }, k_theta, k_phi);
    EXPECT_NEAR(c.c[0].x, 0.886227f, 1e-3f);
    EXPECT_NEAR(c.c[1].x, 1.023327f, 1e-3f);
    EXPECT_NEAR(c.c[6].x, -0.247708f, 1e-3f);
    EXPECT_NEAR(c.c[8].x, -0.429043f, 1e-3f);
    for (std::size_t i : {2u, 3u, 4u, 5u, 7u}) EXPECT_NEAR(c.c[i].x, 0.0f, 1e-4f) << i;
}

TEST(project_radiance, clamped_cosine_lobe_about_any_direction_matches_hand_values) {
    // Ramamoorthi & Hanrahan 2001, Eq. 8 and the addition theorem: max(0, n.w) has band-l
    // coefficients sqrt(4 pi / (2l + 1)) z_l Y_lm(n) with the zonal z_l = sqrt(pi)/2, sqrt(pi/3),
    // sqrt(5 pi)/8, i.e. c_i = A_l Y_i(n) with A = pi, 2 pi/3, pi/4. For n = (2, 1, 2)/3:
    //   Y(n) = 0.282095, 0.488603 (1/3, 2/3, 2/3), 1.092548 (2/9, 2/9), 0.315392 (1/3),
    //          1.092548 (4/9), 0.546274 (1/3)
    //   c    = 0.886227, 0.341109, 0.682218, 0.682218, 0.190686, 0.190686, 0.082569, 0.381371,
    //          0.143014.
    // The lobe's kink is not on a grid line here, hence the finer grid.
    const glm::vec3 n(2.0f / 3.0f, 1.0f / 3.0f, 2.0f / 3.0f);
    const sh9_rgb c = project_radiance(
        [n](glm::vec3 w) { return glm::vec3(std::max(0.0f, glm::dot(n, w))); }, 128, 256);
    const sh9 expected = {0.886227f, 0.341109f, 0.682218f, 0.682218f, 0.190686f,
                          0.190686f, 0.082569f, 0.381371f, 0.143014f};
    for (std::size_t i = 0; i < 9; ++i) EXPECT_NEAR(c.c[i].x, expected[i], 5e-4f) << i;
}

TEST(sh_coefficient_count, is_the_square_of_the_band_count) {
    static_assert(sh_coefficient_count(1) == 1);
    static_assert(sh_coefficient_count(2) == 4);
    static_assert(sh_coefficient_count(k_sh_bands) == 9);
    EXPECT_EQ(sh_coefficient_count(2), 4);
}

TEST(project_radiance, first_four_coefficients_are_the_best_two_band_fit) {
    // The claim in spherical_harmonics.h: truncating 9 coefficients to 4 gives the 2-band
    // projection. Checked against an independent least-squares fit of f by Y_0..Y_3 on the
    // quadrature grid (normal equations G a = b with the grid's own Gram matrix G), for a
    // function with strong band-2 and higher content that a wrong truncation would leak into.
    const glm::vec3 lobe = glm::normalize(glm::vec3(-0.6f, 0.5f, 0.8f));
    const auto f = [lobe](glm::vec3 w) {
        return std::exp(2.0f * glm::dot(w, lobe)) + 3.0f * w.x * w.z - w.y * w.y;
    };
    constexpr int n_theta = 96;
    constexpr int n_phi = 192;
    const sh9_rgb c =
        project_radiance([&](glm::vec3 w) { return glm::vec3(f(w)); }, n_theta, n_phi);
    double gram[4][5] = {};  // augmented [G | b]
    for (int j = 0; j < n_theta; ++j) {
        const double theta = (j + 0.5) * std::numbers::pi / n_theta;
        const double weight =
            std::sin(theta) * (std::numbers::pi / n_theta) * (2.0 * std::numbers::pi / n_phi);
        for (int i = 0; i < n_phi; ++i) {
            const double phi = (i + 0.5) * 2.0 * std::numbers::pi / n_phi;
            const glm::vec3 w(float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)),
                              float(-std::sin(theta) * std::cos(phi)));
            const sh9 y = sh_basis(w);
            for (int r = 0; r < 4; ++r) {
                for (int k = 0; k < 4; ++k)
                    gram[r][k] += weight * y[std::size_t(r)] * y[std::size_t(k)];
                gram[r][4] += weight * y[std::size_t(r)] * f(w);
            }
        }
    }
    for (int col = 0; col < 4; ++col) {  // Gauss-Jordan; G is close to the identity
        for (int k = 4; k >= col; --k) gram[col][k] /= gram[col][col];
        for (int r = 0; r < 4; ++r) {
            if (r == col) continue;
            const double m = gram[r][col];
            for (int k = col; k < 5; ++k) gram[r][k] -= m * gram[col][k];
        }
    }
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(c.c[i].x, gram[i][4], 2e-3) << i;
    // Sanity that the check can fail: the band-2 content is large.
    EXPECT_GT(std::abs(c.c[7].x), 0.5f);
}

TEST(irradiance_from_radiance, clamped_cosine_lobe_seen_from_its_axis) {
    // True E(up) = integral of cos^2 over the hemisphere = 2 pi / 3 = 2.0944. The 9 terms give
    // A0 c0 Y0 + A1 c1 Y1 + A2 (c6 Y6 + c8 Y8) = pi/4 + pi/3 + 5 pi/64 = 127 pi / 192 = 2.0780.
    const sh9_rgb e = irradiance_from_radiance(project_radiance(
        [](glm::vec3 w) { return glm::vec3(clamped_cosine_about_up(w)); }, k_theta, k_phi));
    EXPECT_NEAR(evaluate(e, k_up).x, 127.0f * k_pi / 192.0f, 2e-3f);
}

TEST(irradiance_from_radiance, directional_light_through_nine_terms) {
    // A directional light of irradiance E along d has c_i = E Y_i(d). At n = d the irradiance is
    // E sum_l A_l sum_m Y_lm(d)^2 = E sum_l A_l (2l+1)/(4 pi) (addition theorem)
    //   = E (1/4 + 1/2 + 5/16) = 17/16 E    (true value E: the truncation overshoots 6.25 %);
    // at n = -d: E (1/4 - 1/2 + 5/16) = E/16, and at n perpendicular (P1 = 0, P2 = -1/2):
    // E (1/4 - 5/32) = 3/32 E (true value 0 for both: the lobe rings into the far side).
    const glm::vec3 d = glm::normalize(glm::vec3(0.3f, 0.8f, -0.5f));
    const glm::vec3 perpendicular = glm::normalize(glm::cross(d, glm::vec3(1.0f, 0.0f, 0.0f)));
    const float e = 2.5f;
    const sh9_rgb irr = irradiance_from_radiance(project_directional_light(d, glm::vec3(e)));
    EXPECT_NEAR(evaluate(irr, d).x, 17.0f / 16.0f * e, 1e-4f);
    EXPECT_NEAR(evaluate(irr, -d).x, 1.0f / 16.0f * e, 1e-4f);
    EXPECT_NEAR(evaluate(irr, perpendicular).x, 3.0f / 32.0f * e, 1e-4f);
}

TEST(project_radiance, small_bright_cap_converges_to_the_directional_light) {
    // A 3 degree cap about up with radiance E / solid angle carries irradiance E. Integrated on
    // 1 degree rings, its projection must match the delta's within the cap's own blur
    // (band 2 averages P2 over the cap: 1 - 3 alpha^2 / 4 = 0.998).
    const float alpha = 3.0f * k_pi / 180.0f;
    const float solid_angle = 2.0f * k_pi * (1.0f - std::cos(alpha));
    const float e = 4.0f;
    const sh9_rgb cap = irradiance_from_radiance(project_radiance(
        [&](glm::vec3 w) { return glm::vec3(w.y > std::cos(alpha) ? e / solid_angle : 0.0f); }, 180,
        360));
    const sh9_rgb delta = irradiance_from_radiance(project_directional_light(k_up, glm::vec3(e)));
    for (glm::vec3 n : probe_directions()) {
        EXPECT_NEAR(evaluate(cap, n).x, evaluate(delta, n).x, 5e-3f * e) << n.x << n.y << n.z;
    }
    EXPECT_NEAR(evaluate(cap, k_up).x, 17.0f / 16.0f * e, 5e-3f * e);
}

TEST(project_radiance, huge_and_tiny_intensities_stay_finite_and_proportional) {
    for (float scale : {1e30f, 1e-30f}) {
        const sh9_rgb e = irradiance_from_radiance(
            project_radiance([scale](glm::vec3) { return glm::vec3(scale); }, 16, 32));
        for (glm::vec3 n : probe_directions()) {
            const float v = evaluate(e, n).x;
            ASSERT_TRUE(std::isfinite(v));
            EXPECT_NEAR(v / scale, k_pi, 2e-2f) << scale;
        }
        const sh9_rgb sun =
            irradiance_from_radiance(project_directional_light(k_up, glm::vec3(scale)));
        EXPECT_NEAR(evaluate(sun, k_up).x / scale, 17.0f / 16.0f, 1e-4f);
    }
}

TEST(project_radiance, infinite_radiance_is_held_and_nan_carries_nothing) {
    // Policy (spherical_harmonics.h): +-inf clamps to k_sh_max_radiance, NaN counts as 0.
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const sh9_rgb e = irradiance_from_radiance(project_radiance(
        [&](glm::vec3 w) { return glm::vec3(inf, -inf, w.y > 0.0f ? nan : 1.0f); }, 16, 32));
    for (glm::vec3 n : probe_directions()) {
        const glm::vec3 v = evaluate(e, n);
        EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
        EXPECT_GT(v.x, 0.0f);
        EXPECT_LT(v.y, 0.0f);
    }
    // Blue is 1 below the horizon, 0 above: down minus up is 2 A1 c1 Y1 = 2 (2 pi/3)(3/4pi) pi = pi
    // (to the coarse 16 x 32 grid's accuracy).
    EXPECT_NEAR(evaluate(e, glm::vec3(0.0f, -1.0f, 0.0f)).z - evaluate(e, k_up).z, k_pi, 5e-2f);
}

}  // namespace
}  // namespace sylva
