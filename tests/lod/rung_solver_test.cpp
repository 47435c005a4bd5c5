// The auto ladder's solver (lod/rung_solver.h) on hand-built tables: interpolation in log size,
// each plant's choice at a multiplier λ, the λ that holds a budget against the known optimum,
// and hysteresis around a switch point.
#include "lod/rung_solver.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sylva {
namespace {

// Three rungs as (error, cost µs): A (0, 100), B (b_error, 20), C (c_error, 1). Breakpoints:
// A -> B at λ = b_error / 80, B -> C at λ = (c_error - b_error) / 19.
rung_candidates three(float b_error, float c_error) {
    rung_candidates c;
    c.count = 3;
    c.error = {0.0f, b_error, c_error};
    c.cost_us = {100.0f, 20.0f, 1.0f};
    return c;
}

constexpr std::uint8_t k_none = std::uint8_t(k_max_rungs);

TEST(rung_solver, tables_are_interpolated_linearly_in_log_size_and_held_beyond) {
    std::array<float, k_rung_table_size_count> t{10.0f, 20.0f, 40.0f, 80.0f, 160.0f, 320.0f, 640.0f};
    EXPECT_FLOAT_EQ(interpolate_table(t, 8.0f), 10.0f);
    EXPECT_FLOAT_EQ(interpolate_table(t, 16.0f), 20.0f);
    // √(16·32) is halfway between 16 and 32 in log size.
    EXPECT_NEAR(interpolate_table(t, std::sqrt(16.0f * 32.0f)), 30.0f, 1e-4f);
    EXPECT_FLOAT_EQ(interpolate_table(t, 2.0f), 10.0f);
    EXPECT_FLOAT_EQ(interpolate_table(t, 1e5f), 640.0f);
    EXPECT_FLOAT_EQ(interpolate_table(t, std::nanf("")), 10.0f);
}

TEST(rung_solver, a_plant_takes_the_rung_minimising_error_plus_lambda_cost) {
    const rung_candidates c = three(10.0f, 50.0f);  // breakpoints 0.125 and 40/19 = 2.105
    EXPECT_EQ(choose_at(c, 0.0, k_none, 0.0f), 0);
    EXPECT_EQ(choose_at(c, 0.1, k_none, 0.0f), 0);
    EXPECT_EQ(choose_at(c, 0.125, k_none, 0.0f), 1) << "a tie goes to the cheaper rung";
    EXPECT_EQ(choose_at(c, 0.2, k_none, 0.0f), 1);
    EXPECT_EQ(choose_at(c, 2.0, k_none, 0.0f), 1);
    EXPECT_EQ(choose_at(c, 2.2, k_none, 0.0f), 2);
}

TEST(rung_solver, lambda_holds_the_budget_at_the_known_optimum) {
    // Plant 1 breaks at 0.125 and 2.105, plant 2 at 30/80 = 0.375 and 30/19 = 1.579.
    const rung_candidates p1 = three(10.0f, 50.0f), p2 = three(30.0f, 60.0f);
    lambda_histogram h;
    h.add(p1);
    h.add(p2);
    EXPECT_DOUBLE_EQ(h.cost_at_zero_us, 200.0);
    const auto total = [&](double lambda, double& error) {
        const std::uint8_t a = choose_at(p1, lambda, k_none, 0.0f), b = choose_at(p2, lambda, k_none, 0.0f);
        error = double(p1.error[a] + p2.error[b]);
        return double(p1.cost_us[a] + p2.cost_us[b]);
    };
    double error = 0.0;
    EXPECT_EQ(solve_lambda(h, 500.0), 0.0) << "a budget above the least-error cost needs no multiplier";
    // Budget 120 µs: the optimum over all 9 choices is (B, A), cost 120, error 10.
    double lambda = solve_lambda(h, 120.0);
    EXPECT_GE(lambda, 0.125);
    EXPECT_LT(lambda, 0.375);
    EXPECT_EQ(total(lambda, error), 120.0);
    EXPECT_EQ(error, 10.0);
    // Budget 50 µs: (B, B), cost 40, error 40 (the cheaper (B, C) costs 21 for error 70).
    lambda = solve_lambda(h, 50.0);
    EXPECT_EQ(total(lambda, error), 40.0);
    EXPECT_EQ(error, 40.0);
    // Below every plant's cheapest: the cheapest rungs, λ at the top of the range.
    lambda = solve_lambda(h, 1.0);
    EXPECT_EQ(lambda, k_lambda_max);
    EXPECT_EQ(total(lambda, error), 2.0);
}

TEST(rung_solver, the_bucket_edges_cover_the_lambda_range_geometrically) {
    EXPECT_NEAR(lambda_bucket_edge(k_lambda_buckets - 1), k_lambda_max, 1e-6 * k_lambda_max);
    EXPECT_NEAR(lambda_bucket_edge(k_lambda_buckets / 2 - 1), 1.0, 1e-9);  // 1e-6 .. 1e6: 1 is halfway
    EXPECT_NEAR(lambda_bucket_edge(1) / lambda_bucket_edge(0), lambda_bucket_edge(101) / lambda_bucket_edge(100), 1e-9);
}

TEST(rung_solver, a_plant_oscillating_around_a_switch_point_changes_rung_once) {
    const rung_candidates c = three(10.0f, 50.0f);  // A -> B at λ = 0.125
    // λ wobbles around the breakpoint (as a plant's size or the budget would), then moves on to
    // 0.2, then wobbles again: with 5 % hysteresis the plant changes from A to B once.
    const std::array<double, 12> lambdas{0.1, 0.13, 0.12, 0.13, 0.12, 0.13, 0.2, 0.12, 0.13, 0.12, 0.13, 0.12};
    std::uint8_t rung = k_none;
    int changes = 0;
    for (const double lambda : lambdas) {
        const std::uint8_t next = choose_at(c, lambda, rung, 0.05f);
        changes += rung != k_none && next != rung;
        rung = next;
    }
    EXPECT_EQ(changes, 1);
    EXPECT_EQ(rung, 1);
    // Without hysteresis the same wobble flips it every frame.
    rung = k_none;
    changes = 0;
    for (const double lambda : lambdas) {
        const std::uint8_t next = choose_at(c, lambda, rung, 0.0f);
        changes += rung != k_none && next != rung;
        rung = next;
    }
    EXPECT_EQ(changes, 10);
}

TEST(rung_solver, candidates_come_from_the_species_tables_at_the_plant_size) {
    species_rung_tables s;
    rung_table mesh{representation::mesh_full, {}, {}}, cloud{representation::billboard_cloud, {}, {}};
    for (std::size_t i = 0; i < k_rung_table_size_count; ++i) {
        mesh.error[i] = 1.0f;
        mesh.cost_us[i] = 500.0f;
        cloud.error[i] = float(i);
        cloud.cost_us[i] = 50.0f;
    }
    s.rungs = {mesh, cloud};
    const rung_candidates c = candidates_at(s, 64.0f);  // table index 3
    ASSERT_EQ(c.count, 2);
    EXPECT_EQ(c.error[1], 3.0f);
    EXPECT_EQ(c.cost_us[0], 500.0f);
}

}  // namespace
}  // namespace sylva
