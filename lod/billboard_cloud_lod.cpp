#include "lod/billboard_cloud_lod.h"

#include <algorithm>

#include "lod/distance_lod.h"

namespace sylva {
namespace {

// One band around `switch_m` between `nearer` and `farther`, at `distance_m` inside it.
cloud_lod_choice blend(representation nearer, representation farther, float switch_m, float distance_m) {
    const float t = std::clamp((distance_m - switch_m * (1.0f - k_cloud_band)) / (2.0f * k_cloud_band * switch_m),
                               0.0f, 1.0f);
    if (t < 0.5f) return {nearer, farther, 2.0f * t};
    return {farther, nearer, 2.0f * (1.0f - t)};
}

}  // namespace

float cloud_switch_distance(const species_entry& species, float cloud_distance_m) {
    constexpr float k_no_overlap = (1.0f - k_cloud_band) / (1.0f + k_cloud_band);
    return std::min(cloud_distance_m, species.far_distance_m * k_no_overlap);
}

cloud_lod_choice choose_cloud_lod(const species_entry& species, float cloud_distance_m, float distance_m,
                                  float scale, float lod_scale) {
    const float factor = scale * lod_scale;
    const float cloud_m = cloud_switch_distance(species, cloud_distance_m) * factor;
    const float far_m = species.far_distance_m * factor;
    if (distance_m < cloud_m * (1.0f - k_cloud_band))
        return {choose_representation(species, distance_m, scale, lod_scale)};
    if (distance_m < cloud_m * (1.0f + k_cloud_band)) {
        // The mesh level the plant would have at the band's near edge (the band lies below the
        // far distance, so this is the full or the reduced mesh).
        const representation mesh =
            choose_representation(species, cloud_m * (1.0f - k_cloud_band), scale, lod_scale);
        return blend(mesh, representation::billboard_cloud, cloud_m, distance_m);
    }
    if (distance_m < far_m * (1.0f - k_cloud_band)) return {representation::billboard_cloud};
    if (distance_m < far_m * (1.0f + k_cloud_band))
        return blend(representation::billboard_cloud, representation::crossed_billboard, far_m, distance_m);
    return {representation::crossed_billboard};
}

float cloud_alpha_threshold(float fade) {
    const float f = std::clamp(fade, 0.0f, 1.0f);
    if (f >= 0.75f) return 0.75f + (k_cloud_threshold_shown - 0.75f) * (f - 0.75f) / 0.25f;
    if (f >= 0.5f) return 0.90f + (0.75f - 0.90f) * (f - 0.5f) / 0.25f;
    return k_cloud_threshold_gone + (0.90f - k_cloud_threshold_gone) * f / 0.5f;
}

}  // namespace sylva
