#include "lod/distance_lod.h"

#include "lod/billboard_cloud_lod.h"

namespace sylva {

representation choose_representation(const species_entry& species, float distance_m, float scale,
                                      float lod_scale) {
    const float factor = scale * lod_scale;
    if (distance_m < species.reduced_distance_m * factor) return representation::mesh_full;
    if (distance_m < species.far_distance_m * factor) return representation::mesh_reduced;
    return representation::mesh_far;
}

representation choose_representation(const lod_policy& policy, const species_entry& species, float distance_m,
                                     float scale, float lod_scale) {
    switch (policy.mode) {
        case lod_policy::kind::single: return policy.near;
        // The point/line representation covers every distance: its prefixes shrink with the
        // projected size (update_point_prefix), down to polygons near and a few points far.
        case lod_policy::kind::points_lines: return representation::points;
        case lod_policy::kind::billboard_clouds:
            return choose_cloud_lod(species, policy.cloud_distance_m, distance_m, scale, lod_scale).primary;
        case lod_policy::kind::hard_switch:
            // A NaN distance compares false and so takes the far side, like the distance levels.
            return distance_m < policy.switch_distance_m * scale * lod_scale ? policy.near : policy.far;
        // A ladder chooses by projected size, which needs the camera: select_representation
        // calls choose_rung (lod/ladder.h) itself and never comes here.
        case lod_policy::kind::ladder:
        case lod_policy::kind::distance_levels: break;
    }
    return choose_representation(species, distance_m, scale, lod_scale);
}

}  // namespace sylva
