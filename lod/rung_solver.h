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
// Hysteresis: a plant keeps its previous rung until λ has moved past the breakpoint between it
// and the best rung by the fraction `hysteresis` (kept while error_prev + λ·cost_prev exceeds
// the best by at most hysteresis·λ·|cost_prev − cost_best|), so a plant whose size or budget
// wobbles around a breakpoint does not flicker. The band is in λ, not a share of the value: a
// share of error + λ·cost is wide where a species' rungs all have large, close errors (grass),
// and held 1,400 plants of `landscape` on a rung the budget could no longer pay for three frames.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "components/lod_state.h"
#include "lod/ladder.h"

namespace sylva {

// Projected sizes (px) at which a species' tables are sampled; between them a value is
// interpolated linearly in log size, beyond them it is held.
// From 2 px: most of a meadow's grass is that small, and there a crossed billboard's
// alpha-tested texture keeps far less of the plant's coverage than at 8 px.
inline constexpr std::array<float, 9> k_rung_table_sizes_px{2.0f,   4.0f,   8.0f,   16.0f, 32.0f,
                                                            64.0f, 128.0f, 256.0f, 512.0f};
inline constexpr std::size_t k_rung_table_size_count = k_rung_table_sizes_px.size();

// One rung of a species: its expected image error (summed over the plant's pixels, so errors of
// plants add up) and its cost (microseconds) at each table size: drawing it in the view, and
// casting its shadow (a plant may do either without the other).
struct rung_table {
    representation rung = representation::none;
    std::array<float, k_rung_table_size_count> error{};
    std::array<float, k_rung_table_size_count> cost_us{};
    std::array<float, k_rung_table_size_count> shadow_cost_us{};
    // Of the shadow's cost, what shading its fragments took, and the metres per shadow-map texel
    // they were shaded at (0: not known). A shadow covers a fixed area of the sun's view, so its
    // fragments go with the inverse square of the texel: a plant casting into a coarser cascade
    // than the table's costs that much less (candidates_at).
    std::array<float, k_rung_table_size_count> shadow_fragment_cost_us{};
    std::array<float, k_rung_table_size_count> shadow_texel_m{};
    // The pixels the rung covers alone in the view at each size (resources/seen_pixels.h: what
    // a frame's count of the plant's pixels is a share of).
    std::array<float, k_rung_table_size_count> drawn_pixels{};
};

// A species' rungs in ladder order (at most k_max_rungs), and the pixels its full geometry
// covers at each table size (what an error per pixel is taken over).
struct species_rung_tables {
    std::vector<rung_table> rungs;
    std::array<float, k_rung_table_size_count> plant_pixels{};
};

// `table` at `size_px` (log-linear between samples, held beyond; a NaN size takes the smallest).
float interpolate_table(const std::array<float, k_rung_table_size_count>& table, float size_px);

// One plant's candidates at its size: error and cost of each rung of its species.
struct rung_candidates {
    std::array<float, k_max_rungs> error{};
    std::array<float, k_max_rungs> cost_us{};
    float plant_pixels = 0.0f;
    std::uint8_t count = 0;
};
// What the last frame showed of a plant (resources/seen_pixels.h): its pixels there and the rung
// (an index into its tables) it was drawn with; pixels below 0 or no rung: not known, whole.
struct shown_last_frame {
    float pixels = -1.0f;
    std::uint8_t rung = k_max_rungs;
};

// The least difference in mean colour error per plant pixel (0..1) the solver pays for: half an
// 8-bit step, less on average than the smallest change a pixel of the plant can show. Below it
// two rungs' tables tell them apart by their measurement more than by their images:
// single_tree's oak at 430 px as points at d' = 1 (every triangle as a prefix) had 1354.0 against
// the full mesh's 1355.2 (a thousandth apart) for 1.8x its cost, and the budget's rounding put
// the tree on points and then, once it cast a shadow, on the mesh: an eleven-frame dissolve drawing
// both (the auto ladder at 1.08-1.19x the mesh levels' time for the same image).
inline constexpr float k_error_resolution_per_pixel = 1.0f / 510.0f;

// A plant only casting (outside the view, inside the shadow range) costs its shadow and shows
// no error of its own, so it takes its cheapest rung; one seen beyond the shadow range costs
// its view only. A seen plant's errors are weighed by the share of its pixels the last frame
// showed, `shown` over what its rung then covers alone at this size (at most 1), as the image
// shows them. `caster_texel_m` is the texel of the finest cascade the plant casts into this
// frame: its shadow fragments cost (table texel / caster_texel_m)² of the table's (0: as the
// table says). A rung no better than a cheaper one by k_error_resolution_per_pixel over the
// plant's (seen) pixels is given that cheaper rung's error.
rung_candidates candidates_at(const species_rung_tables& tables, float size_px, bool seen = true, bool casts = true,
                              shown_last_frame shown = {}, float caster_texel_m = 0.0f);

// The rung index minimising error + λ·cost, ties to the cheaper rung; `previous` (an index, or
// k_max_rungs for none) is kept within the `hysteresis` band above.
std::uint8_t choose_at(const rung_candidates& c, double lambda, std::uint8_t previous, float hysteresis);

// The cheapest rung whose error is at most `max_error` (summed over the plant's pixels, as the
// candidates' errors are), ties to the lesser error; the least-error rung when none is. `previous`
// is kept while its error stays within (1 + hysteresis)·max_error and its cost within
// (1 + hysteresis) of the choice's, so a plant at the threshold does not flicker.
std::uint8_t cheapest_within(const rung_candidates& c, double max_error, std::uint8_t previous, float hysteresis);

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
    double cheapest_cost_us() const;             // every plant on its cheapest rung
};

// The multiplier that holds `budget_us`: `at` is the least bucket edge (or 0) whose total cost
// is within it (k_lambda_max when none is: every plant on its cheapest rung then). Many plants
// of a species at similar sizes share a bucket, so the cost can fall by far more than needed
// across it; only a `share` of that bucket's savings is taken: a plant uses `at` when its own
// fixed dither in [0, 1) is below `share` and the edge below, `below`, otherwise (the single
// fractional item of the relaxed knapsack, rounded per plant as Deussen's sample counts are,
// lod/point_line_lod.h sample_dither). The total then lands within one plant's saving of the
// budget in expectation, and a plant's λ changes only when `share` crosses its dither. A plant
// the share moves to `at` is given at / (1 − hysteresis), past the band that would keep it on its
// dearer rung (choose_at), so that the savings the share counted on are made: on `landscape`
// under a falling budget, without it, half a bucket of 2,000 trees stayed on their reduced
// meshes for seven frames while the budget fell to a fifth.
struct lambda_choice {
    double below = 0.0;
    double at = 0.0;
    double share = 0.0;
    double for_plant(double dither, float hysteresis) const {
        return dither < share ? at / (1.0 - double(hysteresis)) : below;
    }
};
lambda_choice solve_lambda(const lambda_histogram& h, double budget_us);

}  // namespace sylva
