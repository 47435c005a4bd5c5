#include "systems/update_shells_system.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "ecs/parallel.h"
#include "lod/ladder.h"
#include "lod/point_line_lod.h"
#include "systems/cull_system.h"

namespace sylva {

float distance_for_size(float diameter_m, float size_px, double pixel_units) {
    return float(double(diameter_m) / (double(size_px) * pixel_units));
}

void update_shells_system::run(ecs::system_context<update_shells_system>& ctx) {
    shell_view& view = ctx.resource_mut<shell_view>();
    if (!view.active) return;
    const camera& cam = ctx.single<camera>();
    const lod_policy& policy = ctx.resource<lod_policy>();
    const double pixel = image_plane_units(1.0, double(cam.fov_y), double(cam.viewport_height_px));
    const auto& species = ctx.resource<species_library>().species;
    // Sizes as select_representation sees them: lod_scale and the ladders' size scale stretch the
    // handover, so its distances move with them.
    const double stretch = double(cam.lod_scale) * double(policy.ladder_size_scale);
    // The shell is one layer over the terrain, so its handover is one distance band for all its
    // plants: the farthest any species' ladder asks (a species whose plants hand over nearer keeps
    // its previous rung out to there; none vanishes before the shell shows it).
    view.fade_start_m = 0.0f;
    view.fade_end_m = 0.0f;
    for (std::size_t k = 0; k < policy.ladders.size() && k < species.size(); ++k) {
        const ladder& l = policy.ladders[k];
        if (policy.mode != lod_policy::kind::ladder || !l.reaches(representation::shell)) continue;
        const float below = l.below_px[l.count - 1];  // the shell is the last rung
        const float band = l.band[l.count - 1];
        const float scale = k < view.mean_scale.size() ? view.mean_scale[k] : 1.0f;
        const float diameter = float(double(2.0f * species[k].bounding_radius * scale) * stretch);
        const float end = distance_for_size(diameter, below, pixel);
        if (end <= view.fade_end_m) continue;
        view.plant_diameter_m = 2.0f * species[k].bounding_radius * scale;
        view.fade_start_m = distance_for_size(diameter, below * (1.0f + band), pixel);
        view.fade_end_m = end;
    }
    const glm::vec3 eye = glm::vec3(cam.position - view.terrain_origin);
    const float pixels_per_radian = float(1.0 / pixel);
    view.pixels_per_radian = pixels_per_radian;
    const frustum_planes frustum = extract_frustum_planes(cam.projection * cam.view);
    const glm::dvec3 to_camera_relative = view.terrain_origin - cam.position;
    auto& tiles = ctx.write<shell_tile>();
    shell_tile* data = tiles.data();
    ctx.parallel_for(tiles.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t i = begin; i < end; ++i) {
            data[i].visible = sphere_in_frustum(frustum, glm::vec3(glm::dvec3(data[i].centre) + to_camera_relative),
                                                data[i].radius);
            const float nearest = std::max(glm::length(data[i].centre - eye) - data[i].radius, 1e-3f);
            data[i].grid =
                coarsest_ground_grid(std::span(data[i].grid_error_m).first(data[i].grids), nearest,
                                     pixels_per_radian, k_shell_ground_error_px);
            data[i].level = shell_level_at(nearest, view.slice_height_m, pixels_per_radian, k_shell_min_spacing_px,
                                           view.max_level, k_shell_merge_band);
        }
    });
}

}  // namespace sylva
