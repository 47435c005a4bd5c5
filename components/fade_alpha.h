#pragma once
// Cross-fade between two representations during a transition (Behrendt 2005 §2.3: between the
// billboard cloud and the polygonal plant near the viewer, and between the cloud and the two
// crossed billboards far away). Sort-free: the primary representation (lod_state::current) is
// drawn at `value`, the partner at `partner_value`; neither is blended. A billboard cloud fades
// by raising its alpha threshold, every other representation by a stable screen-door dissolve
// (shaders/surface.frag). Outside a transition band `partner` is none and `value` is 1.
// Writer: select_representation; read by build_draw_list.
#include <cstdint>

#include "components/lod_state.h"

namespace sylva {

struct fade_alpha {
    float value = 1.0f;          // how much of the primary is drawn, 0 (nothing) .. 1 (all)
    float partner_value = 0.0f;  // the same for the partner
    representation partner = representation::none;  // drawn besides current during a band
};
static_assert(sizeof(fade_alpha) == 12);

}  // namespace sylva
