#include "app/one_plant_view.h"

#include <algorithm>
#include <cmath>

#include "app/scenario_player.h"
#include "components/transform.h"
#include "lod/point_line_lod.h"
#include "resources/playback.h"

namespace sylva {

scenario species_alone(const scenario& s, std::size_t i, std::uint32_t view_px, const std::string& purpose) {
    scenario one = s;
    // Only what changes the measurement stays (it keys the cache): the species, the seed its
    // model grows from, the light, the shadows, the ground's colour.
    one.name = s.species[i].name + ":" + purpose;
    one.width = one.height = view_px;
    one.frames = 1;
    one.fps = scenario{}.fps;
    one.camera = camera_settings{};
    const lod_settings lod = s.lod;
    one.lod = lod_settings{};
    one.lod.lighting = lod.lighting;
    one.lod.sh_bands = lod.sh_bands;
    one.lod.sh_interreflection = lod.sh_interreflection;
    one.world_offset = glm::dvec3(0.0);
    one.species = {s.species[i]};
    one.species[0].max_distance_m = 1e6f;  // never culled at the smallest size
    one.species[0].ladder.clear();
    population_settings p;
    p.species = s.species[i].name;
    p.count = 1;
    p.min_spacing_m = 0.5f;
    p.scale_min = p.scale_max = 1.0f;
    p.area = {-0.5, -0.5, 0.5, 0.5};
    one.populations = {p};
    one.terrain = terrain_settings{};
    one.terrain.size_m = 64.0;
    one.terrain.resolution = 9;
    one.terrain.height_m = 0.0f;
    one.terrain.ground_color = s.terrain.ground_color;
    one.eco_tiles.enabled = false;
    return one;
}

scenario species_patch(const scenario& s, std::size_t i, std::uint32_t view_px, const std::string& purpose) {
    scenario patch = species_alone(s, i, view_px, purpose);
    // The densest of the species' populations: where its plants stand closest, and most often
    // side by side in a frame.
    const population_settings* densest = nullptr;
    double densest_per_m2 = 0.0;
    for (const population_settings& p : s.populations) {
        const double area = std::abs((p.area[2] - p.area[0]) * (p.area[3] - p.area[1]));
        if (p.species != s.species[i].name || p.count == 0 || area <= 0.0) continue;
        const double per_m2 = double(p.count) / area;
        if (per_m2 > densest_per_m2) densest = &p, densest_per_m2 = per_m2;
    }
    if (densest == nullptr) return patch;  // no population: alone, as a frame would show it
    population_settings& p = patch.populations[0];
    // At the population's sizes: from the scenario's eye height a smaller plant at the same
    // projected size is seen closer, so from higher above.
    p.scale_min = densest->scale_min;
    p.scale_max = densest->scale_max;
    // No more plants than the population has: a lone tree (single_tree) is the plant alone,
    // species_alone's scenario itself when the population does not vary its size, so that its
    // tables measure it once (rung_tables.cpp).
    const double plants = std::min(k_patch_plants, double(densest->count));
    if (plants < 2.0) return patch;
    const double side = std::min(std::sqrt(plants / densest_per_m2), k_patch_max_side_m);
    p.count = std::uint32_t(std::max(1.0, std::round(side * side * densest_per_m2)));
    p.min_spacing_m = densest->min_spacing_m;
    p.area = {-0.5 * side, -0.5 * side, 0.5 * side, 0.5 * side};
    patch.terrain.size_m = std::max(patch.terrain.size_m, 2.0 * side + 32.0);
    return patch;
}

void aim_at_plant(scenario_player& player, float size_px, float azimuth_deg, std::uint32_t view_px,
                  double eye_height_m) {
    ecs::world& world = player.world();
    // The plant nearest the origin: the only one of species_alone, the middle of species_patch.
    const auto& table = world.table<world_transform>();
    const world_transform* plants = table.data();
    const auto from_origin = [](const world_transform& p) { return p.position.x * p.position.x + p.position.z * p.position.z; };
    const world_transform& t = *std::min_element(plants, plants + table.size(), [&](const auto& a, const auto& b) {
        return from_origin(a) < from_origin(b);
    });
    const species_entry& species = world.resource<species_library>().species[0];
    const double pixel = image_plane_units(1.0, double(k_one_plant_fov_deg) * M_PI / 180.0, double(view_px));
    // select_representation measures from the eye to the plant's base.
    const double d = 2.0 * double(species.bounding_radius * t.scale) / (double(size_px) * pixel);
    const double centre = double(species.center_height * t.scale);
    // From the scenario's eye height; closer than the eye is high, the eye stays off the
    // vertical (at most 72 degrees down), where a camera keeps its distance.
    const bool level = eye_height_m < 0.0;
    const double eye_height = level ? std::min(centre, 0.7 * d) : std::min(eye_height_m, 0.95 * d);
    const double across = std::sqrt(std::max(d * d - eye_height * eye_height, 0.0));
    const double a = double(azimuth_deg) * M_PI / 180.0;
    camera_keyframe key;
    key.position = t.position + glm::dvec3(across * std::sin(a), eye_height, across * std::cos(a));
    key.target = t.position + glm::dvec3(0.0, centre, 0.0);
    key.fov_deg = k_one_plant_fov_deg;
    world.resource<camera_track>().keys = {key};
    player.set_frame(0);
}

}  // namespace sylva
