#pragma once
// Cross-fade between two representations during a transition, 0 (old) to 1 (new). Behrendt 2005
// fades billboard clouds by a distance-dependent alpha threshold, so no sorting is needed.
// Writer: the transition system; read by build_draw_list.
namespace sylva {

struct fade_alpha {
    float value = 1.0f;
};
static_assert(sizeof(fade_alpha) == 4);

}  // namespace sylva
