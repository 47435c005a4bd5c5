#include "systems/adapt_plant_budget_system.h"

#include <algorithm>
#include <cmath>

namespace sylva {

double next_plant_budget(double current_us, double target_ms, const plant_budget_feedback& f) {
    if (!(target_ms > 0.0) || !(f.measured_ms > 0.0) || !std::isfinite(f.measured_ms)) return current_us;
    double next = spent_budget_us(current_us, f);
    if (std::abs(std::log(f.measured_ms / target_ms)) > std::log1p(k_plant_budget_dead_band)) {
        const double from = next;
        next = from * target_ms / f.measured_ms;
        // The secant through the last two frames where both the budget and the time moved enough
        // to tell the slope over the noise, when it points the same way, at most twice the
        // ratio's step in log space.
        const double db = from - f.previous_budget_us, dm = f.measured_ms - f.previous_ms;
        if (f.previous_budget_us > 0.0 && f.previous_ms > 0.0 &&
            std::abs(std::log(from / f.previous_budget_us)) > std::log(k_plant_budget_secant_step) &&
            std::abs(dm) > k_plant_budget_secant_signal * f.measured_ms && db / dm > 0.0) {
            const double secant = from + (target_ms - f.measured_ms) * db / dm;
            const double ratio = target_ms / f.measured_ms;
            if ((secant - from) * (next - from) > 0.0)
                next = std::clamp(secant, from * std::min(ratio, ratio * ratio), from * std::max(ratio, ratio * ratio));
        }
        next = std::clamp(next, from / k_plant_budget_max_step, from * k_plant_budget_max_step);
    }
    if (f.most_us > 0.0) next = std::clamp(next, std::min(f.least_us, f.most_us), f.most_us);  // no wind-up
    return next;
}

void adapt_plant_budget_system::run(ecs::system_context<adapt_plant_budget_system>& ctx) {
    rung_budget& budget = ctx.resource_mut<rung_budget>();
    if (!budget.active() || !(budget.target_frame_ms > 0.0) || budget.max_error > 0.0) return;
    plant_budget_feedback f;
    f.measured_ms = ctx.resource<frame_stats>().gpu_ms;
    f.least_us = budget.least_possible_us;
    f.most_us = budget.most_useful_us;
    f.previous_budget_us = budget.controller_budget_us;
    f.previous_ms = budget.controller_ms;
    if (f.measured_ms > 0.0) {  // this frame's point for the next secant
        budget.controller_budget_us = spent_budget_us(budget.plant_budget_us, f);
        budget.controller_ms = f.measured_ms;
    }
    budget.plant_budget_us = next_plant_budget(budget.plant_budget_us, budget.target_frame_ms, f);
}

}  // namespace sylva
