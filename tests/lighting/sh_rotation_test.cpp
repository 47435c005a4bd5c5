#include "lighting/sh_rotation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <vector>

#include "lighting/sky_model.h"

namespace sylva {
namespace {

// A 3-band function with every coefficient non-zero and different per channel, so no symmetry
// can hide a wrong matrix entry.
sh9_rgb asymmetric_coefficients() {
    sh9_rgb c;
    const sh9 values = {1.3f, -0.7f, 0.45f, 0.9f, -0.35f, 0.6f, 0.25f, -0.8f, 0.55f};
    for (std::size_t i = 0; i < 9; ++i)
        c.c[i] = glm::vec3(values[i], 0.5f * values[8 - i], float(i) * 0.1f - 0.3f);
    return c;
}

glm::mat3 rotation(float angle_deg, glm::vec3 axis) {
    return glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(angle_deg), glm::normalize(axis)));
}

std::vector<glm::mat3> test_rotations() {
    return {rotation(90.0f, {0, 1, 0}), rotation(37.0f, {1, 0, 0}), rotation(-123.0f, {0, 0, 1}),
            rotation(71.0f, {1, 2, 3}), rotation(180.0f, {-0.4f, 0.3f, 0.87f})};
}

std::vector<glm::vec3> probe_directions() {
    std::vector<glm::vec3> out;
    for (int j = 0; j < 7; ++j)
        for (int i = 0; i < 11; ++i) {
            const float theta = (float(j) + 0.5f) / 7.0f * 3.14159265f;
            const float phi = float(i) / 11.0f * 6.2831853f;
            out.emplace_back(std::sin(theta) * std::cos(phi), std::cos(theta),
                             std::sin(theta) * std::sin(phi));
        }
    return out;
}

void expect_coefficients_near(const sh9_rgb& a, const sh9_rgb& b, float tolerance) {
    for (std::size_t i = 0; i < 9; ++i)
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(a.c[i][ch], b.c[i][ch], tolerance) << i << "/" << ch;
}

TEST(rotate, moves_the_function_exactly_for_bands_zero_to_two) {
    // g = rotate(f, R) must satisfy g(R d) = f(d) everywhere. No quadrature is involved, so the
    // only error is float rounding (coefficients of order 1, 9 terms).
    const sh9_rgb f = asymmetric_coefficients();
    for (const glm::mat3& r : test_rotations()) {
        const sh9_rgb g = rotate(f, r);
        for (glm::vec3 d : probe_directions()) {
            const glm::vec3 expected = evaluate(f, d);
            const glm::vec3 got = evaluate(g, r * d);
            for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(got[ch], expected[ch], 2e-5f);
        }
    }
}

TEST(rotate, equals_reprojecting_the_rotated_function) {
    // A smooth function with content in every band (also above band 2, which the projection
    // drops before or after turning alike): rotating its projection must equal projecting
    // f(R^T w) directly, to the quadrature's accuracy on the fine grid (the midpoint rule in
    // theta leaves ~1e-4 of coefficients up to ~5; rotation itself is exact, test above).
    const glm::vec3 lobe = glm::normalize(glm::vec3(1.0f, 2.0f, -0.5f));
    const auto f = [lobe](glm::vec3 w) {
        const float s = std::exp(1.5f * glm::dot(w, lobe));
        return glm::vec3(s * (1.0f + 0.3f * w.x), s + w.z * w.y, 2.0f + w.x * w.z);
    };
    const sh9_rgb projected = project_radiance(f, 128, 256);
    for (const glm::mat3& r : test_rotations()) {
        const glm::mat3 r_inverse = glm::transpose(r);
        const sh9_rgb direct =
            project_radiance([&](glm::vec3 w) { return f(r_inverse * w); }, 128, 256);
        expect_coefficients_near(rotate(projected, r), direct, 6e-4f);
    }
}

TEST(rotate, keeps_band_zero_and_each_band_norm) {
    // Band 0 is invariant; rotation acts orthogonally within each band (sum of squares kept).
    const sh9_rgb f = asymmetric_coefficients();
    for (const glm::mat3& r : test_rotations()) {
        const sh9_rgb g = rotate(f, r);
        EXPECT_EQ(g.c[0], f.c[0]);
        for (int ch = 0; ch < 3; ++ch) {
            float band1_f = 0, band1_g = 0, band2_f = 0, band2_g = 0;
            for (std::size_t i = 1; i < 4; ++i) {
                band1_f += f.c[i][ch] * f.c[i][ch];
                band1_g += g.c[i][ch] * g.c[i][ch];
            }
            for (std::size_t i = 4; i < 9; ++i) {
                band2_f += f.c[i][ch] * f.c[i][ch];
                band2_g += g.c[i][ch] * g.c[i][ch];
            }
            EXPECT_NEAR(band1_g, band1_f, 1e-5f);
            EXPECT_NEAR(band2_g, band2_f, 1e-5f);
        }
    }
}

TEST(rotate, by_identity_leaves_the_coefficients) {
    const sh9_rgb f = asymmetric_coefficients();
    expect_coefficients_near(rotate(f, glm::mat3(1.0f)), f, 1e-6f);
}

TEST(rotate, composes_like_the_rotations) {
    const sh9_rgb f = asymmetric_coefficients();
    const glm::mat3 a = rotation(71.0f, {1, 2, 3});
    const glm::mat3 b = rotation(-40.0f, {0.2f, -1.0f, 0.4f});
    expect_coefficients_near(rotate(rotate(f, a), b), rotate(f, b * a), 1e-5f);
    // And is not commutative: b a differs from a b, so the order above is checked.
    const sh9_rgb ab = rotate(f, a * b);
    float difference = 0.0f;
    for (std::size_t i = 0; i < 9; ++i) difference += glm::length(ab.c[i] - rotate(f, b * a).c[i]);
    EXPECT_GT(difference, 0.1f);
}

TEST(rotate, quarter_turn_about_up_by_hand) {
    // 90 degrees about +y (right-handed) maps (x, y, z) to (z, y, -x), so g(w) = f(R^T w) with
    // R^T w = (-w.z, w.y, w.x): the "z" lobe (index 2) becomes the "x" lobe (index 3), and
    // x z (index 7) becomes (-z) x = -x z.
    const glm::mat3 r = rotation(90.0f, {0, 1, 0});
    sh9 z_lobe{};
    z_lobe[2] = 1.0f;
    const sh9 turned = rotate(z_lobe, r);
    for (std::size_t i = 0; i < 9; ++i) EXPECT_NEAR(turned[i], i == 3 ? 1.0f : 0.0f, 1e-6f) << i;
    sh9 xz{};
    xz[7] = 1.0f;
    const sh9 turned_xz = rotate(xz, r);
    for (std::size_t i = 0; i < 9; ++i)
        EXPECT_NEAR(turned_xz[i], i == 7 ? -1.0f : 0.0f, 1e-6f) << i;
}

TEST(rotate, stays_finite_for_extreme_coefficients) {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const glm::mat3 r = rotation(71.0f, {1, 2, 3});
    for (float scale : {0.0f, 1e-30f, 1e30f}) {
        sh9_rgb f = asymmetric_coefficients();
        for (auto& c : f.c) c *= scale;
        const sh9_rgb g = rotate(f, r);
        const sh9_rgb unit = rotate(asymmetric_coefficients(), r);
        for (std::size_t i = 0; i < 9; ++i) {
            ASSERT_TRUE(std::isfinite(g.c[i].x) && std::isfinite(g.c[i].y) &&
                        std::isfinite(g.c[i].z));
            if (scale > 0.0f)
                EXPECT_NEAR(g.c[i].x / scale, unit.c[i].x, 1e-5f) << scale << " " << i;
            else
                EXPECT_EQ(g.c[i], glm::vec3(0.0f));
        }
    }
    sh9 wild = {inf, -inf, nan, 3.4e38f, -3.4e38f, nan, inf, 1.0f, -inf};
    for (float v : rotate(wild, r)) EXPECT_TRUE(std::isfinite(v));
}

TEST(azimuth_rotation, moves_the_sun_along_its_azimuth) {
    for (float delta : {10.0f, 90.0f, -135.0f}) {
        const glm::vec3 from = sun_direction_from_angles(30.0f, 140.0f);
        const glm::vec3 to = sun_direction_from_angles(30.0f, 140.0f + delta);
        const glm::vec3 got = azimuth_rotation(delta) * from;
        EXPECT_NEAR(got.x, to.x, 1e-6f);
        EXPECT_NEAR(got.y, to.y, 1e-6f);
        EXPECT_NEAR(got.z, to.z, 1e-6f);
    }
}

}  // namespace
}  // namespace sylva
