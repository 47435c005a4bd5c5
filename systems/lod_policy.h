#pragma once
// How select_representation chooses, as a world resource: the runtime's own distance levels, or
// one of the fixed policies the bench compares them with (issue 4: "each representation on its
// own", and the typical engine baseline "full mesh near, one crossed-quad billboard beyond a
// distance, hard switch").
#include <cstdint>

#include "components/lod_state.h"

namespace sylva {

struct lod_policy {
    enum class kind : std::uint8_t {
        distance_levels,  // the species' mesh levels by distance (select_representation_system.h)
        single,           // every drawn plant as `near`
        hard_switch,      // `near` closer than switch_distance_m times the plant's scale, else `far`
    };
    kind mode = kind::distance_levels;
    representation near = representation::mesh_full;
    representation far = representation::mesh_far;
    float switch_distance_m = 50.0f;
};

}  // namespace sylva
