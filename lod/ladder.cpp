#include "lod/ladder.h"

#include "lod/point_line_lod.h"

namespace sylva {

ladder_choice choose_rung(const ladder& l, float size_px) {
    if (l.count == 0) return {};
    if (std::isnan(size_px)) return {l.rungs[l.count - 1]};
    // The first step whose band's small edge lies below the size: the plant is above its band,
    // in it, or (no such step) on the last rung.
    for (std::size_t i = 1; i < l.count; ++i) {
        const float s = l.below_px[i], h = l.band[i];
        if (size_px >= s * (1.0f + h)) return {l.rungs[i - 1]};
        if (size_px > s * (1.0f - h)) {
            const float t = std::clamp((s * (1.0f + h) - size_px) / (2.0f * h * s), 0.0f, 1.0f);
            if (t < 0.5f) return {l.rungs[i - 1], l.rungs[i], 2.0f * t};
            return {l.rungs[i], l.rungs[i - 1], 2.0f * (1.0f - t)};
        }
    }
    return {l.rungs[l.count - 1]};
}

ladder_choice choose_rung_with_shell(const ladder& l, float size_px, float shell_fade) {
    if (l.count < 2 || l.rungs[l.count - 1] != representation::shell) return choose_rung(l, size_px);
    ladder nearer = l;
    --nearer.count;
    const ladder_choice plant = choose_rung(nearer, size_px);
    if (!(shell_fade >= 0.5f)) return plant;
    if (shell_fade >= 1.0f) return {representation::shell};
    return {representation::shell, plant.primary, 2.0f * (1.0f - shell_fade)};
}

float projected_size_px(float radius_m, float distance_m, float fov_y, float viewport_height_px) {
    return projected_size_px(radius_m, distance_m, image_plane_units(1.0, double(fov_y), double(viewport_height_px)));
}

ladder papers_ladder() {
    ladder l;
    const auto add = [&](representation r, float below_px) {
        l.rungs[l.count] = r;
        l.below_px[l.count] = below_px;
        l.band[l.count] = l.count == 0 ? 0.0f : k_default_band;
        ++l.count;
    };
    add(representation::mesh_full, 0.0f);
    add(representation::mesh_reduced, 400.0f);
    add(representation::billboard_cloud, 240.0f);
    add(representation::points, 60.0f);
    add(representation::crossed_billboard, 20.0f);
    return l;
}

}  // namespace sylva
