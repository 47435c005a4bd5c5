// Spearman's rank correlation (measure/rank_correlation.h) by hand.
#include "measure/rank_correlation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sylva {
namespace {

TEST(rank_correlation, orders_alike_reversed_and_by_hand) {
    // Any increasing map keeps the order: 1; a decreasing one reverses it: -1.
    EXPECT_DOUBLE_EQ(spearman_correlation({1, 2, 3, 4}, {10, 20, 300, 4000}), 1.0);
    EXPECT_DOUBLE_EQ(spearman_correlation({1, 2, 3, 4}, {4, 3, 2, 1}), -1.0);
    // Ranks 0 1 2 3 against 1 0 2 3, about their mean 1.5: d_a = (-1.5, -0.5, 0.5, 1.5),
    // d_b = (-0.5, -1.5, 0.5, 1.5); Σ d_a d_b = 0.75 + 0.75 + 0.25 + 2.25 = 4, Σ d² = 5 each: 0.8.
    EXPECT_DOUBLE_EQ(spearman_correlation({1, 2, 3, 4}, {2, 1, 3, 4}), 0.8);
    // A tie shares its ranks' mean: b ranks 0 1.5 1.5 3: Σ d_a d_b = 2.25 + 0 + 0 + 2.25 = 4.5,
    // Σ d_b² = 2.25 + 0 + 0 + 2.25 = 4.5: r = 4.5 / √(5 · 4.5) = 0.9487.
    EXPECT_NEAR(spearman_correlation({1, 2, 3, 4}, {1, 2, 2, 4}), 4.5 / std::sqrt(22.5), 1e-12);
    EXPECT_EQ(spearman_correlation({1, 1, 1}, {1, 2, 3}), 0.0) << "a constant series orders nothing";
    EXPECT_EQ(spearman_correlation({}, {}), 0.0);
}

}  // namespace
}  // namespace sylva
