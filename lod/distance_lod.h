#pragma once
// Which representation a plant takes at a distance, as pure functions: the runtime's own
// distance levels (full mesh near, reduced mesh beyond the species' reduced distance, far mesh
// beyond its far distance) and the choice under each lod_policy. Distances are scaled by the
// plant's size and the camera's lod_scale. select_representation_system applies them to every
// visible plant; billboard_cloud_lod.h uses the distance levels for the mesh side of its bands.
#include "components/lod_state.h"
#include "resources/lod_policy.h"
#include "resources/scene_assets.h"

namespace sylva {

// The representation for a plant at `distance_m` under the distance levels.
representation choose_representation(const species_entry& species, float distance_m, float scale,
                                     float lod_scale);
// The same under a policy (lod_policy::kind::distance_levels gives choose_representation).
representation choose_representation(const lod_policy& policy, const species_entry& species, float distance_m,
                                     float scale, float lod_scale);

}  // namespace sylva
