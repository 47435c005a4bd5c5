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
    std::array<float, k_rung_table_size_count> t{2.5f, 5.0f, 10.0f, 20.0f, 40.0f, 80.0f, 160.0f, 320.0f, 640.0f};
    EXPECT_FLOAT_EQ(interpolate_table(t, 8.0f), 10.0f);
    EXPECT_FLOAT_EQ(interpolate_table(t, 16.0f), 20.0f);
    // √(16·32) is halfway between 16 and 32 in log size.
    EXPECT_NEAR(interpolate_table(t, std::sqrt(16.0f * 32.0f)), 30.0f, 1e-4f);
    EXPECT_FLOAT_EQ(interpolate_table(t, 1.0f), 2.5f);
    EXPECT_FLOAT_EQ(interpolate_table(t, 1e5f), 640.0f);
    EXPECT_FLOAT_EQ(interpolate_table(t, std::nanf("")), 2.5f);
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
    EXPECT_EQ(solve_lambda(h, 500.0).at, 0.0) << "a budget above the least-error cost needs no multiplier";
    // Budget 120 µs: the optimum over all 9 choices is (B, A), cost 120, error 10. All of the
    // bucket's saving is needed: every plant takes `at`.
    EXPECT_EQ(solve_lambda(h, 120.0).share, 1.0);
    double lambda = solve_lambda(h, 120.0).at;
    EXPECT_GE(lambda, 0.125);
    EXPECT_LT(lambda, 0.375);
    EXPECT_EQ(total(lambda, error), 120.0);
    EXPECT_EQ(error, 10.0);
    // Budget 50 µs: (B, B), cost 40, error 40 (the cheaper (B, C) costs 21 for error 70).
    lambda = solve_lambda(h, 50.0).at;
    EXPECT_EQ(total(lambda, error), 40.0);
    EXPECT_EQ(error, 40.0);
    // Below every plant's cheapest: the cheapest rungs, λ at the top of the range.
    lambda = solve_lambda(h, 1.0).at;
    EXPECT_EQ(lambda, k_lambda_max);
    EXPECT_EQ(total(lambda, error), 2.0);
}

// 1000 plants alike, each saving 80 µs at the same breakpoint: a budget needing 30 % of that
// saving moves the 30 % of plants whose dither is below 0.3, not all of them.
TEST(rung_solver, plants_sharing_a_bucket_take_only_the_share_of_it_the_budget_needs) {
    const rung_candidates plant = three(10.0f, 50.0f);
    lambda_histogram h;
    for (int i = 0; i < 1000; ++i) h.add(plant);
    const double budget = 100000.0 - 0.3 * 80000.0;  // all on A cost 100,000; all on B 20,000
    const lambda_choice l = solve_lambda(h, budget);
    EXPECT_NEAR(l.share, 0.3, 1e-12);
    EXPECT_LT(l.below, 0.125);
    EXPECT_GE(l.at, 0.125);
    double cost = 0.0;
    for (int i = 0; i < 1000; ++i) {
        const double dither = (i + 0.5) / 1000.0;  // evenly spread, as hashed seeds are on average
        cost += double(plant.cost_us[choose_at(plant, l.for_plant(dither, 0.0f), k_none, 0.0f)]);
    }
    EXPECT_NEAR(cost, budget, 80.0) << "within one plant's saving of the budget";
    // Every plant on A before, with 5 % hysteresis: the share still moves, hysteresis or not.
    cost = 0.0;
    for (int i = 0; i < 1000; ++i) {
        const double dither = (i + 0.5) / 1000.0;
        cost += double(plant.cost_us[choose_at(plant, l.for_plant(dither, 0.05f), 0, 0.05f)]);
    }
    EXPECT_NEAR(cost, budget, 80.0) << "hysteresis kept plants the share moved";
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
    s.plant_pixels = {2.5f, 5.0f, 10.0f, 20.0f, 40.0f, 80.0f, 160.0f, 320.0f, 640.0f};
    const rung_candidates c = candidates_at(s, 64.0f);  // table index 5
    ASSERT_EQ(c.count, 2);
    EXPECT_EQ(c.error[1], 5.0f);
    EXPECT_EQ(c.cost_us[0], 500.0f);
    EXPECT_EQ(c.plant_pixels, 80.0f);
}

TEST(rung_solver, a_plant_only_casting_pays_its_shadow_and_shows_no_error) {
    species_rung_tables s;
    rung_table mesh{representation::mesh_full, {}, {}, {}}, quad{representation::crossed_billboard, {}, {}, {}};
    mesh.error.fill(1.0f);
    mesh.cost_us.fill(500.0f);
    mesh.shadow_cost_us.fill(300.0f);
    quad.error.fill(9.0f);
    quad.cost_us.fill(4.0f);
    quad.shadow_cost_us.fill(8.0f);
    s.rungs = {mesh, quad};
    const rung_candidates both = candidates_at(s, 64.0f);
    EXPECT_EQ(both.cost_us[0], 800.0f);
    EXPECT_EQ(both.error[1], 9.0f);
    const rung_candidates casting = candidates_at(s, 64.0f, false, true);
    EXPECT_EQ(casting.cost_us[0], 300.0f);
    EXPECT_EQ(casting.cost_us[1], 8.0f);
    EXPECT_EQ(casting.error[0], 0.0f);
    EXPECT_EQ(choose_at(casting, 0.0, k_none, 0.0f), 1) << "no error to buy: the cheaper shadow";
    const rung_candidates seen = candidates_at(s, 64.0f, true, false);
    EXPECT_EQ(seen.cost_us[0], 500.0f);
    EXPECT_EQ(seen.error[0], 1.0f);
}

// A shadow's fragments go with the texel area of the cascade it falls in. The tables measured
// the mesh's 300 µs shadow, 200 µs of it fragments, at 0.05 m per texel: cast into a cascade of
// 0.1 m texels it shades a quarter of the fragments, 100 + 200/4 = 150 µs; into one of 0.025 m,
// four times as many, 100 + 800 = 900 µs. Not known on either side: as the table says.
TEST(rung_solver, a_shadow_costs_its_fragments_at_the_texel_of_its_cascade) {
    species_rung_tables s;
    rung_table mesh;
    mesh.rung = representation::mesh_full;
    mesh.shadow_cost_us.fill(300.0f);
    mesh.shadow_fragment_cost_us.fill(200.0f);
    mesh.shadow_texel_m.fill(0.05f);
    s.rungs = {mesh};
    EXPECT_FLOAT_EQ(candidates_at(s, 64.0f, false, true, {}, 0.1f).cost_us[0], 150.0f);
    EXPECT_FLOAT_EQ(candidates_at(s, 64.0f, false, true, {}, 0.025f).cost_us[0], 900.0f);
    EXPECT_FLOAT_EQ(candidates_at(s, 64.0f, false, true, {}, 0.05f).cost_us[0], 300.0f);
    EXPECT_FLOAT_EQ(candidates_at(s, 64.0f, false, true, {}, 0.0f).cost_us[0], 300.0f);
    EXPECT_FLOAT_EQ(candidates_at(s, 64.0f, false, false, {}, 0.1f).cost_us[0], 0.0f) << "casting nothing";
    s.rungs[0].shadow_texel_m.fill(0.0f);
    EXPECT_FLOAT_EQ(candidates_at(s, 64.0f, false, true, {}, 0.1f).cost_us[0], 300.0f);
}

// resources/seen_pixels.h: a plant three quarters hidden shows a quarter of each rung's error.
// Drawn last frame on the quad, which covers 40 pixels alone at this size, it showed 10: a
// quarter. At λ = 0.01 error per µs, whole: mesh 1 + 0.01·500 = 6 against quad 9 + 0.01·4 =
// 9.04, the mesh; a quarter seen: 0.25 + 5 = 5.25 against 2.25 + 0.04 = 2.29, the quad.
TEST(rung_solver, a_plant_mostly_hidden_weighs_its_errors_by_the_share_seen) {
    species_rung_tables s;
    rung_table mesh{representation::mesh_full, {}, {}, {}}, quad{representation::crossed_billboard, {}, {}, {}};
    mesh.error.fill(1.0f);
    mesh.cost_us.fill(500.0f);
    mesh.drawn_pixels.fill(60.0f);
    quad.error.fill(9.0f);
    quad.cost_us.fill(4.0f);
    quad.drawn_pixels.fill(40.0f);
    s.rungs = {mesh, quad};
    const rung_candidates whole = candidates_at(s, 64.0f, true, false);
    EXPECT_EQ(choose_at(whole, 0.01, k_none, 0.0f), 0);
    const rung_candidates quarter = candidates_at(s, 64.0f, true, false, {10.0f, 1});
    EXPECT_FLOAT_EQ(quarter.error[0], 0.25f);
    EXPECT_FLOAT_EQ(quarter.error[1], 2.25f);
    EXPECT_EQ(quarter.cost_us[0], 500.0f) << "what it costs does not depend on what shows";
    EXPECT_EQ(choose_at(quarter, 0.01, k_none, 0.0f), 1);
    // The same 10 pixels drawn with the mesh (60 alone) are a sixth.
    EXPECT_FLOAT_EQ(candidates_at(s, 64.0f, true, false, {10.0f, 0}).error[1], 1.5f);
    // Not known (not drawn last frame), more than alone (a fade), or a rung covering no pixel
    // alone: whole.
    EXPECT_FLOAT_EQ(candidates_at(s, 64.0f, true, false, {-1.0f, 1}).error[1], 9.0f);
    EXPECT_FLOAT_EQ(candidates_at(s, 64.0f, true, false, {80.0f, 1}).error[1], 9.0f);
    EXPECT_FLOAT_EQ(candidates_at(s, 64.0f, true, false, {10.0f, k_none}).error[1], 9.0f);
    quad.drawn_pixels.fill(0.5f);
    s.rungs = {mesh, quad};
    EXPECT_FLOAT_EQ(candidates_at(s, 64.0f, true, false, {0.0f, 1}).error[1], 9.0f);
}

// k_error_resolution_per_pixel: over 5,100 plant pixels the solver tells errors apart from
// 5100 / 510 = 10 on. Points costing 1.8x the mesh for 1354 against 1355.2 are no better (they
// take the mesh's error, so even λ = 0 picks the mesh); the mesh costing 1.8x points for an error
// 11 lower is, and keeps its own.
TEST(rung_solver, a_dearer_rung_better_by_less_than_the_error_resolution_is_no_better) {
    species_rung_tables s;
    rung_table mesh{representation::mesh_full, {}, {}, {}}, points{representation::points, {}, {}, {}};
    mesh.error.fill(1355.2f);
    mesh.cost_us.fill(128000.0f);
    points.error.fill(1354.0f);
    points.cost_us.fill(234000.0f);
    s.rungs = {mesh, points};
    s.plant_pixels.fill(5100.0f);
    const rung_candidates c = candidates_at(s, 430.0f, true, false);
    EXPECT_FLOAT_EQ(c.error[0], 1355.2f);
    EXPECT_FLOAT_EQ(c.error[1], 1355.2f);
    EXPECT_EQ(choose_at(c, 0.0, k_none, 0.0f), 0);
    lambda_histogram h;
    h.add(c);
    EXPECT_DOUBLE_EQ(h.cost_at_zero_us, 128000.0) << "the least-error rung is the mesh";
    // Better by 11 (more than 10): a real difference, kept.
    s.rungs[1].error.fill(1344.2f);
    const rung_candidates better = candidates_at(s, 430.0f, true, false);
    EXPECT_FLOAT_EQ(better.error[1], 1344.2f);
    EXPECT_EQ(choose_at(better, 0.0, k_none, 0.0f), 1);
    // The resolution is over the pixels seen (resources/seen_pixels.h): a quarter seen, errors
    // 338.8 and 336.05 are 2.75 apart, over a quarter's 2.5, so the points keep theirs; half as
    // much better (1349.7: 337.425 against 338.8, 1.375 apart) they take the mesh's.
    s.rungs[0].drawn_pixels.fill(400.0f);
    const rung_candidates quarter = candidates_at(s, 430.0f, true, false, {100.0f, 0});
    EXPECT_FLOAT_EQ(quarter.error[1], 0.25f * 1344.2f);
    s.rungs[1].error.fill(1349.7f);
    EXPECT_FLOAT_EQ(candidates_at(s, 430.0f, true, false, {100.0f, 0}).error[1], 0.25f * 1355.2f);
}

// --max-error: with 100 plant pixels a threshold of 0.05 per pixel allows an error of 5 in all.
TEST(rung_solver, under_an_error_threshold_a_plant_takes_the_cheapest_rung_within_it) {
    rung_candidates c = three(2.0f, 10.0f);
    c.plant_pixels = 100.0f;
    const double limit = 0.05 * double(c.plant_pixels);
    EXPECT_EQ(cheapest_within(c, limit, k_none, 0.05f), 1) << "B (error 2) is within 5, C (10) is not";
    EXPECT_EQ(cheapest_within(c, 10.0, k_none, 0.05f), 2) << "C is within 10 and cheapest";
    EXPECT_EQ(cheapest_within(c, 1.0, k_none, 0.05f), 0) << "only A (error 0) is within 1";
    // Nothing within: the least-error rung, whatever it costs.
    rung_candidates bad = three(2.0f, 10.0f);
    bad.error[0] = 3.0f;
    EXPECT_EQ(cheapest_within(bad, 1.0, k_none, 0.05f), 1);
    EXPECT_EQ(cheapest_within(c, limit, 0, 0.05f), 1) << "A costs 100, not within 1.05 x B's 20";
    // C at 5.2 is over 5 but within 5 x 1.05 = 5.25: a plant already on C stays, a new one takes B.
    const rung_candidates near = three(2.0f, 5.2f);
    EXPECT_EQ(cheapest_within(near, 5.0, 2, 0.05f), 2);
    EXPECT_EQ(cheapest_within(near, 5.0, k_none, 0.05f), 1);
    EXPECT_EQ(cheapest_within(near, 5.0, 2, 0.0f), 1) << "without hysteresis the threshold is strict";
}

}  // namespace
}  // namespace sylva
