#pragma once
// Deussen 2002 §5.4: "the sampling distance d' can be varied dynamically to ensure a desired
// vertex complexity. This enables animations with nearly constant frame rates." Each frame this
// system compares what the previous frame cost with the budget (a primitive budget, counted in
// triangle equivalents with the device's costs, or a frame time) and moves d' towards it.
//
// The control law works in log space. Far plants are points, whose number goes as 1/d'² (Eq. 1),
// so log cost ≈ C − s·log d' with s <= 2 (near parts are polygons, independent of d', and
// lines go as 1/d', so s is smaller there). The step
//     log d'_next = log d' + (gain / 2)·(log cost − log budget)
// multiplies the error by 1 − gain·s/2 per frame: with gain 0.7 that is 0.3 where points
// dominate and never negative for s <= 2, so d' settles without overshoot or oscillation.
// A ±2 % dead band keeps it still once it is there; a step is at most a factor of 4.
//
// A primitive budget is deterministic (counts do not depend on timing); a frame-time budget is
// not, and is meant for interactive walkthroughs, not for tests or measurement.
#include "ecs/system.h"
#include "resources/draw_list.h"
#include "resources/frame_stats.h"
#include "resources/lod_policy.h"

namespace sylva {

// The budget d' is adapted to (a world resource; both zero: d' stays as set).
struct sample_distance_budget {
    double primitives = 0.0;  // triangle equivalents per frame (points and lines weighed by cost)
    double frame_ms = 0.0;    // GPU milliseconds per frame
    float min_sample_distance_px = 0.25f;
    float max_sample_distance_px = 64.0f;
    float gain = 0.7f;
};

inline constexpr double k_sample_distance_dead_band = 0.02;
inline constexpr double k_sample_distance_max_step = 4.0;

// The next d' (pixels) for a frame that cost `measured` against `budget` (same unit). Pure.
float next_sample_distance(float current_px, double measured, double budget, const sample_distance_budget& b);

// The previous frame's primitives in triangle equivalents: T + P·c_point/c_tri + L·c_line/c_tri.
double triangle_equivalents(const draw_list& list, const primitive_costs& costs);

struct adapt_sample_distance_system {
    static constexpr std::string_view k_name = "adapt_sample_distance";
    static constexpr ecs::phase k_phase = ecs::phase::simulate;
    using reads = ecs::reads<draw_list, frame_stats, primitive_costs, sample_distance_budget>;
    using writes = ecs::writes<lod_policy>;
    static void run(ecs::system_context<adapt_sample_distance_system>& ctx);
};

}  // namespace sylva
