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

void aim_at_plant(scenario_player& player, float size_px, float azimuth_deg, std::uint32_t view_px,
                  double eye_height_m) {
    ecs::world& world = player.world();
    const world_transform& t = world.table<world_transform>().data()[0];
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
