#include "lighting/filtered_normal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace sylva {
namespace {

// By hand: a unit normal is lit as max(n.l, 0); inside the spread the parabola (mu + w)^2 / 4w:
// w = 0.5, mu = 0 -> 0.25 / 2 = 0.125; mu = 0.25 -> 0.5625 / 2 = 0.28125; mu = -0.25 -> 0.0625 /
// 2 = 0.03125; w = 1, mu = 0 -> 1/4.
TEST(filtered_normal, the_clamped_cosine_of_a_spread_of_normals_by_hand) {
    EXPECT_FLOAT_EQ(filtered_clamped_cosine(0.6f, 0.0f), 0.6f);
    EXPECT_FLOAT_EQ(filtered_clamped_cosine(-0.6f, 0.0f), 0.0f);
    EXPECT_FLOAT_EQ(filtered_clamped_cosine(0.0f, 0.5f), 0.125f);
    EXPECT_FLOAT_EQ(filtered_clamped_cosine(0.25f, 0.5f), 0.28125f);
    EXPECT_FLOAT_EQ(filtered_clamped_cosine(-0.25f, 0.5f), 0.03125f);
    EXPECT_FLOAT_EQ(filtered_clamped_cosine(0.0f, 1.0f), 0.25f);
    // It meets max(mu, 0) at the spread's ends: w at mu = w, 0 at mu = -w.
    EXPECT_FLOAT_EQ(filtered_clamped_cosine(0.5f, 0.5f), 0.5f);
    EXPECT_FLOAT_EQ(filtered_clamped_cosine(-0.5f, 0.5f), 0.0f);
    EXPECT_FLOAT_EQ(filtered_clamped_cosine(0.4999f, 0.5f), (0.9999f * 0.9999f) / 2.0f);
}

// Normals spread evenly over the sphere average to the zero vector (w = 1, mu = 0): their mean
// clamped cosine, counted, is the function's 1/4 (the mean normal lit as max(mu, 0) gives 0).
TEST(filtered_normal, normals_spread_over_the_sphere_are_lit_a_quarter) {
    std::mt19937 random(7);
    std::normal_distribution<double> gauss;
    double sum = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double x = gauss(random), y = gauss(random), z = gauss(random);
        sum += std::max(0.0, z / std::sqrt(x * x + y * y + z * z));  // the sun straight up
    }
    EXPECT_NEAR(sum / n, filtered_clamped_cosine(0.0f, 1.0f), 0.003);
}

}  // namespace
}  // namespace sylva
