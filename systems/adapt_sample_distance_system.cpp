#include "systems/adapt_sample_distance_system.h"

#include <algorithm>
#include <cmath>

namespace sylva {

float next_sample_distance(float current_px, double measured, double budget, const sample_distance_budget& b) {
    if (!(budget > 0.0) || !(measured > 0.0) || !std::isfinite(measured)) return current_px;
    const double error = std::log(measured / budget);
    if (std::abs(error) <= std::log1p(k_sample_distance_dead_band)) return current_px;
    // Deussen 2002 §5.4: cost ∝ d'^-s, s <= 2 (Eq. 1); see the header for the law and its gain.
    const double max_step = std::log(k_sample_distance_max_step);
    const double step = std::clamp(0.5 * double(b.gain) * error, -max_step, max_step);
    const double next = double(current_px) * std::exp(step);
    return float(std::clamp(next, double(b.min_sample_distance_px), double(b.max_sample_distance_px)));
}

double triangle_equivalents(const draw_list& list, const primitive_costs& costs) {
    return double(list.triangles) + double(list.points) * costs.point / costs.triangle +
           double(list.lines) * costs.line / costs.triangle;
}

void adapt_sample_distance_system::run(ecs::system_context<adapt_sample_distance_system>& ctx) {
    const sample_distance_budget& budget = ctx.resource<sample_distance_budget>();
    lod_policy& policy = ctx.resource_mut<lod_policy>();
    if (policy.mode != lod_policy::kind::points_lines) return;
    float& d = policy.points.sample_distance_px;
    if (budget.primitives > 0.0) {
        const draw_list& list = ctx.resource<draw_list>();
        if (list.items.empty()) return;  // the first frame: nothing measured yet
        d = next_sample_distance(d, triangle_equivalents(list, ctx.resource<primitive_costs>()), budget.primitives,
                                 budget);
    } else if (budget.frame_ms > 0.0) {
        d = next_sample_distance(d, ctx.resource<frame_stats>().gpu_ms, budget.frame_ms, budget);
    }
}

}  // namespace sylva
