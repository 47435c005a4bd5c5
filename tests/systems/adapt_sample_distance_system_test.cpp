// Deussen 2002 §5.4: d' adapted every frame to hold a primitive budget. The control law against
// hand values, and on a plant-like cost model: it settles within a few frames of a camera jump
// and does not oscillate.
#include "systems/adapt_sample_distance_system.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace sylva {
namespace {

TEST(adapt_sample_distance, a_frame_four_times_over_budget_doubles_d_prime_at_gain_one) {
    sample_distance_budget b;
    b.gain = 1.0f;
    // log d' += ½·log 4 → d' × 2 (points go as 1/d'², so twice d' is a quarter of the points).
    EXPECT_NEAR(next_sample_distance(1.0f, 4e5, 1e5, b), 2.0f, 1e-5);
    EXPECT_NEAR(next_sample_distance(2.0f, 0.25e5, 1e5, b), 1.0f, 1e-5);
    b.gain = 0.7f;
    EXPECT_NEAR(next_sample_distance(1.0f, 4e5, 1e5, b), std::pow(4.0f, 0.35f), 1e-5);  // 1.6245
}

TEST(adapt_sample_distance, holds_still_inside_the_dead_band_and_steps_at_most_a_factor_of_four) {
    const sample_distance_budget b;
    EXPECT_EQ(next_sample_distance(1.5f, 1.01e5, 1e5, b), 1.5f);
    EXPECT_EQ(next_sample_distance(1.5f, 0.99e5, 1e5, b), 1.5f);
    EXPECT_NEAR(next_sample_distance(1.0f, 1e12, 1e5, b), 4.0f, 1e-5);
    EXPECT_NEAR(next_sample_distance(1.0f, 1e-3, 1e5, b), 0.25f, 1e-6);  // also the lower clamp
    EXPECT_EQ(next_sample_distance(1.0f, 0.0, 1e5, b), 1.0f);            // nothing drawn: no signal
    EXPECT_EQ(next_sample_distance(1.0f, 5e5, 0.0, b), 1.0f);            // no budget
    EXPECT_EQ(next_sample_distance(1.0f, std::nan(""), 1e5, b), 1.0f);
}

// A landscape's cost as a function of d': K/d'² points (Eq. 1) plus F polygons and L/d' lines.
struct cost_model {
    double points = 0.0, lines = 0.0, polygons = 0.0;
    double operator()(double d) const { return points / (d * d) + lines / d + polygons; }
};

TEST(adapt_sample_distance, settles_within_a_few_frames_after_a_camera_jump_without_oscillating) {
    const sample_distance_budget b;  // gain 0.7
    const double budget = 1e5;
    float d = 1.0f;
    cost_model scene{8e5, 5e4, 2e4};
    std::vector<double> error;
    for (int frame = 0; frame < 60; ++frame) {
        if (frame == 30) scene = {8e6, 2e5, 2e4};  // the camera jumps into a dense forest
        const double cost = scene(d);
        error.push_back(cost / budget - 1.0);
        d = next_sample_distance(d, cost, budget, b);
    }
    // Within 5 % of the budget by frame 6 and by 6 frames after the jump; inside the dead band later.
    for (int f = 6; f < 30; ++f) EXPECT_LT(std::abs(error[std::size_t(f)]), 0.05) << f;
    for (int f = 36; f < 60; ++f) EXPECT_LT(std::abs(error[std::size_t(f)]), 0.05) << f;
    // No overshoot: the error keeps its sign while it converges (it may only reach the band).
    for (int f = 1; f < 60; ++f) {
        const double e = error[std::size_t(f)];
        EXPECT_TRUE(e > 0.0 || std::abs(e) <= 0.02) << "overshoot at frame " << f << ": " << e;
    }
}

TEST(adapt_sample_distance, triangle_equivalents_weigh_points_and_lines_by_their_cost) {
    draw_list list;
    list.triangles = 1000;
    list.points = 3000;
    list.lines = 600;
    // The paper's costs (3 : 1 : 2): 1000 + 3000/3 + 600·2/3 = 2400.
    EXPECT_DOUBLE_EQ(triangle_equivalents(list, {}), 2400.0);
    // llvmpipe-like (1 : 0.5 : 4): 1000 + 1500 + 2400 = 4900.
    EXPECT_DOUBLE_EQ(triangle_equivalents(list, {1.0, 0.5, 4.0}), 4900.0);
}

}  // namespace
}  // namespace sylva
