#pragma once
// The auto ladder under a frame-time target (issue 21 item 3, `--target-frame-ms` with
// representation "ladder"): each frame this system compares the GPU time the previous frame took
// with the target and scales the plants' predicted-cost budget (resources/rung_budget.h) by
// their ratio; select_representation then solves for that budget as usual.
//
//     B_next = B · target / measured
//
// The frame is what the plants cost plus what they do not (terrain, sky, shadow set-up): o + k·B.
// The step maps B to target·B / (o + k·B), which is increasing and concave with its fixed point
// where the frame is the target, so from below the budget climbs to it without overshoot, each
// frame's error shrinking by o / target. The predicted costs (the device calibration's) need not
// match the clock: only the ratio of frames is used. Where the rest of the frame is most of it
// that is slow (on `landscape` at 480x270 the terrain alone takes half of a 200 ms frame), so
// while the budget still moves by more than a quarter a frame and the frame by more than 5 %,
// the step is the secant through the last two frames instead, B + (target − measured)·ΔB/Δmeasured,
// which lands on the target at once where the frame is linear in B. It is taken only when it
// steps the same way as the ratio and at most twice as far in log space (gain 2, exact where
// the plants are half the frame): a secant through two noisy frames can point anywhere.
//
// The budget starts with every plant on its cheapest rung and climbs (unless plant_budget_ms
// gives a start). That is not only caution: a plant that moves to a cheaper rung draws its old
// rung too while it dissolves (fade_frames frames), so a cut takes effect only frames later and
// costs more meanwhile, while a plant moving up dissolves a cheap rung. On `landscape`, started
// at the target, the same law swung from 0.4 to 1.5 times it. A ±2 % dead band keeps the
// budget still once there; a step is at most a factor of 8; the budget stays between every plant
// on its cheapest rung and every plant on its least-error rung (what select_representation
// found last frame), so an unreachable target does not wind it up or down without end.
#include <algorithm>

#include "ecs/system.h"
#include "resources/frame_stats.h"
#include "resources/rung_budget.h"

namespace sylva {

inline constexpr double k_plant_budget_dead_band = 0.02;
inline constexpr double k_plant_budget_max_step = 8.0;
inline constexpr double k_plant_budget_secant_step = 1.25;   // the budget moved by a quarter
inline constexpr double k_plant_budget_secant_signal = 0.05;  // and the frame by 5 %

// What the last frame measured, and the budgets that bound the next.
struct plant_budget_feedback {
    double measured_ms = 0.0;  // the GPU frame
    double least_us = 0.0;     // every plant on its cheapest rung
    double most_us = 0.0;      // every plant on its least-error rung (0: unknown, no bound)
    // The frame before: its budget and time (0: none), for the secant.
    double previous_budget_us = 0.0;
    double previous_ms = 0.0;
};

// The budget the last frame was actually drawn with: below every plant on its cheapest rung a
// budget buys nothing (the frame measured that).
inline double spent_budget_us(double current_us, const plant_budget_feedback& f) {
    return f.most_us > 0.0 ? std::max(current_us, std::min(f.least_us, f.most_us)) : current_us;
}

// The next budget (µs) for `target_ms`. Pure; a frame without a measurement keeps it.
double next_plant_budget(double current_us, double target_ms, const plant_budget_feedback& f);

struct adapt_plant_budget_system {
    static constexpr std::string_view k_name = "adapt_plant_budget";
    static constexpr ecs::phase k_phase = ecs::phase::simulate;
    using reads = ecs::reads<frame_stats>;
    using writes = ecs::writes<rung_budget>;
    static void run(ecs::system_context<adapt_plant_budget_system>& ctx);
};

}  // namespace sylva
