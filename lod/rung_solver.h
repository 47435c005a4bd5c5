#pragma once
// The `auto` ladder's choice as pure functions (DESIGN §1.5, issue 21 item 3): each plant may be
// drawn on any rung of its species' ladder, each rung with an expected image error and a cost
// that depend on the plant's projected size; choose one rung per plant so that the summed error
// is least while the summed cost stays within a budget.
//
// That is a multiple-choice knapsack. Its Lagrangian relaxation is solved exactly enough and in
// O(plants): for a multiplier λ >= 0 each plant independently takes the rung minimising
// error + λ·cost, and the total cost C(λ) falls as λ rises. A plant's choice only ever moves
// along the lower convex hull of its (cost, error) points, switching from one hull vertex to the
// next cheaper one at the breakpoint λ_k = Δerror / Δcost between them. Every plant adds its
// breakpoints' cost savings to a histogram over log λ (fixed buckets, summed per chunk and then
// in chunk order, so the result is bit-identical for any thread count); the smallest bucket edge
// at which the remaining cost is within the budget is λ. Every plant then chooses at λ, which
// keeps the total within the budget (up to the hysteresis below), and no λ from a coarser
// bucket grid could buy less error, bar the plants whose breakpoints share λ's bucket.
//
// Hysteresis: a plant keeps its previous rung unless another rung's error + λ·cost is lower by
// more than `hysteresis` of it, so a plant whose two best rungs are nearly tied does not flicker
// between them from frame to frame.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "components/lod_state.h"
#include "lod/ladder.h"

namespace sylva {

// Projected sizes (px) at which a species' tables are sampled; between them a value is
// interpolated linearly in log size, beyond them it is held.
inline constexpr std::array<float, 7> k_rung_table_sizes_px{8.0f, 16.0f, 32.0f, 64.0f, 128.0f, 256.0f, 512.0f};
inline constexpr std::size_t k_rung_table_size_count = k_rung_table_sizes_px.size();

// One rung of a species: its expected image error (summed over the plant's pixels, so errors of
// plants add up) and its cost (microseconds) at each table size.
struct rung_table {
    representation rung = representation::none;
    std::array<float, k_rung_table_size_count> error{};
    std::array<float, k_rung_table_size_count> cost_us{};
};

// A species' rungs in ladder order (at most k_max_rungs).
struct species_rung_tables {
    std::vector<rung_table> rungs;
};

// `table` at `size_px` (log-linear between samples, held beyond; a NaN size takes the smallest).
float interpolate_table(const std::array<float, k_rung_table_size_count>& table, float size_px);

// One plant's candidates at its size: error and cost of each rung of its species.
struct rung_candidates {
    std::array<float, k_max_rungs> error{};
    std::array<float, k_max_rungs> cost_us{};
    std::uint8_t count = 0;
};
rung_candidates candidates_at(const species_rung_tables& tables, float size_px);

// The rung index minimising error + λ·cost, ties to the cheaper rung; `previous` (an index, or
// k_max_rungs for none) is kept unless beaten by more than `hysteresis` (a fraction) of its value.
std::uint8_t choose_at(const rung_candidates& c, double lambda, std::uint8_t previous, float hysteresis);

// The histogram of cost savings over log λ.
inline constexpr std::size_t k_lambda_buckets = 256;
inline constexpr double k_lambda_min = 1e-6;  // error per microsecond
inline constexpr double k_lambda_max = 1e6;
double lambda_bucket_edge(std::size_t bucket);  // the upper edge of `bucket`

struct lambda_histogram {
    double cost_at_zero_us = 0.0;  // every plant on its least-error rung
    std::array<double, k_lambda_buckets + 1> saving_us{};  // [k_lambda_buckets]: beyond k_lambda_max
    void add(const rung_candidates& c);
    void merge(const lambda_histogram& other);  // in chunk order, for a fixed sum order
};

// The least λ (a bucket edge, or 0) whose total cost is within `budget_us`; k_lambda_max when
// none is (every plant on its cheapest rung then).
double solve_lambda(const lambda_histogram& h, double budget_us);

}  // namespace sylva
