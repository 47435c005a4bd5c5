#include "models/noise.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sylva {
namespace {

TEST(noise, gradient_noise_is_zero_on_lattice_points_and_bounded) {
    for (int i = -5; i < 5; ++i) EXPECT_FLOAT_EQ(gradient_noise(i, 2 * i, 11), 0.0f);
    float lo = 0.0f;
    float hi = 0.0f;
    for (int i = 0; i < 20000; ++i) {
        const float v = gradient_noise(i * 0.0731, i * 0.0437, 11);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    EXPECT_GE(lo, -1.0001f);
    EXPECT_LE(hi, 1.0001f);
    EXPECT_LT(lo, -0.3f);
    EXPECT_GT(hi, 0.3f);
}

TEST(noise, period_wraps_the_lattice) {
    for (int i = 0; i < 50; ++i) {
        const double x = i * 0.37;
        const double y = i * 0.11;
        EXPECT_FLOAT_EQ(gradient_noise(x, y, 5, 4), gradient_noise(x + 4.0, y - 8.0, 5, 4));
        EXPECT_FLOAT_EQ(value_noise(x, y, 5, 3), value_noise(x - 3.0, y + 3.0, 5, 3));
    }
    const fbm_settings s{4, 2.0, 0.5f, 2};
    EXPECT_FLOAT_EQ(fbm(0.3, 0.7, 1, s), fbm(2.3, 0.7, 1, s));
}

TEST(noise, seeds_change_the_field) {
    int differ = 0;
    for (int i = 0; i < 20; ++i) differ += gradient_noise(i * 0.3 + 0.1, 0.5, 1) != gradient_noise(i * 0.3 + 0.1, 0.5, 2);
    EXPECT_GT(differ, 15);
}

TEST(noise, value_fbm_is_in_unit_range) {
    const fbm_settings s{5, 2.0, 0.5f, 0};
    for (int i = 0; i < 5000; ++i) {
        const float v = fbm_value(i * 0.173, i * 0.029, 3, s);
        ASSERT_GE(v, 0.0f);
        ASSERT_LE(v, 1.0f);
    }
}

}  // namespace
}  // namespace sylva
