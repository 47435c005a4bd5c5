#pragma once
// Cross-fade between two representations during a transition (Behrendt 2005 §2.3: between the
// billboard cloud and the polygonal plant near the viewer, and between the cloud and the two
// crossed billboards far away). Sort-free: the primary representation (lod_state::current) is
// drawn whole, the partner at `value`; neither is blended (the two overlap across a band, see
// lod/billboard_cloud_lod.h, so the primary never needs to be partial). A billboard cloud
// fades by raising its alpha threshold, every other representation by a stable screen-door
// dissolve (shaders/mesh.frag). Outside a transition band `partner` is none.
// Writer: select_representation; read by build_draw_list.
#include <cstdint>

#include "components/lod_state.h"

namespace sylva {

struct fade_alpha {
    float value = 0.0f;  // how much of the partner is drawn, 0 (nothing) .. 1 (all)
    representation partner = representation::none;  // drawn besides current during a band
};
static_assert(sizeof(fade_alpha) == 8);

}  // namespace sylva
