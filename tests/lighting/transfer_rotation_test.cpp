#include "lighting/transfer_rotation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace sylva {
namespace {

// A band-limited function with every coefficient non-zero, so each entry of the rotation matters.
constexpr sh9 k_coefficients = {0.9f, -0.4f, 0.7f, 0.3f, -0.6f, 0.25f, 0.5f, -0.35f, 0.45f};

float evaluate_scalar(const sh9& c, glm::vec3 w) {
    const sh9 y = sh_basis(w);
    float sum = 0.0f;
    for (std::size_t i = 0; i < 9; ++i) sum += c[i] * y[i];
    return sum;
}

// The world-space position of a model-space direction under the instance yaw (surface.vert).
glm::vec3 yaw_model_to_world(glm::vec3 p, float yaw) {
    const float c = std::cos(yaw), s = std::sin(yaw);
    return {c * p.x + s * p.z, p.y, -s * p.x + c * p.z};
}

TEST(transfer_rotation, matches_reprojecting_the_rotated_function) {
    for (const float yaw : {0.3f, 1.0f, 2.5f, -1.7f}) {
        // g(w) = f(R^T w): the model-space function carried into the world by the yaw.
        const auto rotated = [&](glm::vec3 w) {
            return glm::vec3(evaluate_scalar(k_coefficients, yaw_model_to_world(w, -yaw)));
        };
        const sh9_rgb expected = project_radiance(rotated, 64, 128);
        const sh9 got = rotate_about_y(k_coefficients, yaw);
        for (std::size_t i = 0; i < 9; ++i)
            EXPECT_NEAR(got[i], expected.c[i].x, 2e-3f) << "yaw " << yaw << " i " << i;
    }
}

TEST(transfer_rotation, quarter_turn_of_the_zonal_function_by_hand) {
    // Y6 ~ 3z^2 - 1 turned a quarter about y (model z to world x) is ~ 3x^2 - 1, which on the
    // unit sphere is -1/2 Y6 + (sqrt 3 / 2) Y8 (x^2 = (1 - z^2 + (x^2 - y^2)) / 2).
    sh9 zonal{};
    zonal[6] = 1.0f;
    const sh9 w = rotate_about_y(zonal, std::numbers::pi_v<float> / 2.0f);
    EXPECT_NEAR(w[6], -0.5f, 1e-6f);
    EXPECT_NEAR(w[8], 0.8660254f, 1e-6f);
    EXPECT_NEAR(w[7], 0.0f, 1e-6f);
    // Band 1: model z (index 2) becomes world x (index 3).
    sh9 z{};
    z[2] = 1.0f;
    const sh9 wz = rotate_about_y(z, std::numbers::pi_v<float> / 2.0f);
    EXPECT_NEAR(wz[3], 1.0f, 1e-6f);
    EXPECT_NEAR(wz[2], 0.0f, 1e-6f);
}

TEST(transfer_rotation, keeps_band_energy_and_undoes_itself) {
    const sh9 there = rotate_about_y(k_coefficients, 0.8f);
    const sh9 back = rotate_about_y(there, -0.8f);
    for (std::size_t i = 0; i < 9; ++i) EXPECT_NEAR(back[i], k_coefficients[i], 1e-5f) << i;
    auto band_energy = [](const sh9& c, std::size_t first, std::size_t count) {
        float e = 0.0f;
        for (std::size_t i = first; i < first + count; ++i) e += c[i] * c[i];
        return e;
    };
    EXPECT_NEAR(band_energy(there, 1, 3), band_energy(k_coefficients, 1, 3), 1e-5f);
    EXPECT_NEAR(band_energy(there, 4, 5), band_energy(k_coefficients, 4, 5), 1e-5f);
}

TEST(transfer_rotation, packed_transfer_turns_both_sides) {
    sh9 back{};
    back[2] = -0.5f;
    const vertex_transfer packed = pack_transfer(k_coefficients, back);
    const vertex_transfer turned = rotate_about_y(packed, 1.2f);
    const sh9 front = transfer_side(turned, 0);
    const sh9 expected = rotate_about_y(k_coefficients, 1.2f);
    for (std::size_t i = 0; i < 9; ++i) EXPECT_NEAR(front[i], expected[i], 2e-3f) << i;
    EXPECT_NEAR(transfer_side(turned, 1)[3], -0.5f * std::sin(1.2f), 2e-3f);
}

}  // namespace
}  // namespace sylva
