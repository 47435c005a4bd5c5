#include "systems/spawn_scenario.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <spdlog/spdlog.h>

#include "components/bounds.h"
#include "components/camera.h"
#include "components/environment.h"
#include "components/fade_alpha.h"
#include "components/lod_state.h"
#include "components/plant_instance.h"
#include "components/point_prefix.h"
#include "components/sun.h"
#include "components/transform.h"
#include "models/placement.h"
#include "models/random.h"
#include "models/textures.h"
#include "models/tree_generator.h"
#include "systems/draw_list.h"
#include "systems/frame_stats.h"
#include "systems/lighting/shadow_cascades.h"
#include "systems/playback.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_texture_size = 256;
// The generated ground texture's mean colour is about the scenario default, so tinting by
// ground_color / default recolours the ground while keeping the texture's detail.
constexpr glm::vec3 k_default_ground_color{0.32f, 0.30f, 0.18f};

image_rgba8 tint(image_rgba8 image, glm::vec3 color) {
    const glm::vec3 factor = color / k_default_ground_color;
    for (std::size_t i = 0; i < image.texels.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c)
            image.texels[i + c] = static_cast<std::uint8_t>(
                std::min(255.0f, float(image.texels[i + c]) * factor[int(c)] + 0.5f));
    return image;
}

// Bounding sphere of a mesh standing on its origin: centre on the y axis at mid height.
void fit_bounds(const mesh_data& mesh, species_entry& entry) {
    entry.center_height = 0.5f * (mesh.bounds_min.y + mesh.bounds_max.y);
    const glm::vec3 center{0.0f, entry.center_height, 0.0f};
    float radius = 0.0f;
    for (const auto& v : mesh.vertices) radius = std::max(radius, glm::length(v.position - center));
    entry.bounding_radius = radius;
}

void add_species(scene_assets& assets, const scenario& s, std::size_t index) {
    const species_settings& settings = s.species[index];
    tree_params params = tree_preset(settings.generator);
    params.height_m = settings.height_m;
    const std::uint64_t seed = hash_combine(s.seed, std::uint64_t(index), 0x5eed5eedULL);

    species_entry entry;
    entry.name = settings.name;
    entry.reduced_distance_m = settings.reduced_distance_m;
    entry.far_distance_m = settings.far_distance_m;
    entry.max_distance_m = settings.max_distance_m;
    entry.texture_layer = float(index);
    mesh_data full = generate_tree(params, seed, tree_detail::full);
    mesh_data reduced = generate_tree(params, seed, tree_detail::reduced);
    mesh_data far = generate_tree(params, seed, tree_detail::far);
    fit_bounds(full, entry);
    entry.triangles_full = std::uint32_t(full.triangle_count());
    entry.triangles_reduced = std::uint32_t(reduced.triangle_count());
    entry.triangles_far = std::uint32_t(far.triangle_count());
    entry.mesh_full = std::uint16_t(assets.meshes.size());
    assets.library.meshes.push_back({entry.triangles_full, representation::mesh_full});
    assets.meshes.push_back(std::move(full));
    entry.mesh_reduced = std::uint16_t(assets.meshes.size());
    assets.library.meshes.push_back({entry.triangles_reduced, representation::mesh_reduced});
    assets.meshes.push_back(std::move(reduced));
    entry.mesh_far = std::uint16_t(assets.meshes.size());
    assets.library.meshes.push_back({entry.triangles_far, representation::mesh_far});
    assets.meshes.push_back(std::move(far));
    assets.leaf_textures.push_back(generate_leaf_texture(settings.generator, k_texture_size));
    assets.bark_textures.push_back(generate_bark_texture(settings.generator, k_texture_size));
    assets.library.species.push_back(std::move(entry));
}

}  // namespace

scene_assets build_scene_assets(const scenario& s) {
    scene_assets assets;
    const terrain_settings& t = s.terrain;
    assets.terrain = generate_terrain(t.size_m, t.resolution, t.height_m, t.octaves, t.frequency, t.seed);
    assets.terrain_mesh = std::uint16_t(assets.meshes.size());
    // uv in metres; the ground shader divides by ground_uv_scale_m (the texture's size on the ground).
    assets.meshes.push_back(terrain_mesh(assets.terrain, 1.0f));
    assets.library.meshes.push_back(
        {std::uint32_t(assets.meshes.back().triangle_count()), representation::none});
    assets.ground_texture = tint(generate_ground_texture(k_texture_size), t.ground_color);
    for (std::size_t i = 0; i < s.species.size(); ++i) add_species(assets, s, i);
    return assets;
}

std::vector<camera_keyframe> resolve_camera_keys(const scenario& s, const heightfield& terrain) {
    std::vector<camera_keyframe> keys;
    for (const auto& k : s.camera.keyframes) {
        camera_keyframe key = k.key;
        if (k.above_terrain) {
            key.position.y += terrain.height_at(key.position.x, key.position.z);
            key.target.y += terrain.height_at(key.target.x, key.target.z);
        }
        key.position += s.world_offset;
        key.target += s.world_offset;
        keys.push_back(key);
    }
    return keys;
}

namespace {

std::size_t spawn_plants(ecs::world& world, const scenario& s, const scene_assets& assets) {
    std::size_t spawned = 0;
    for (std::size_t p = 0; p < s.populations.size(); ++p) {
        const population_settings& pop = s.populations[p];
        const auto species_index = std::size_t(
            std::find_if(s.species.begin(), s.species.end(),
                         [&](const species_settings& sp) { return sp.name == pop.species; }) -
            s.species.begin());
        const species_entry& species = assets.library.species.at(species_index);
        const auto placements = place_population(assets.terrain, pop.area, pop.count, pop.min_spacing_m,
                                                 pop.scale_min, pop.scale_max, pop.max_slope_deg,
                                                 hash_combine(s.seed, std::uint64_t(p), 0x9147ULL));
        if (placements.size() < pop.count)
            spdlog::warn("population {} ({}): placed {} of {} plants (no room at {} m spacing)", p,
                         pop.species, placements.size(), pop.count, pop.min_spacing_m);
        for (const auto& pl : placements) {
            const ecs::entity e = world.create();
            const double y = assets.terrain.height_at(pl.xz.x, pl.xz.y);
            world.emplace<world_transform>(
                e, {glm::dvec3(pl.xz.x, y, pl.xz.y) + s.world_offset, pl.yaw, pl.scale});
            world.emplace<bounds>(e, {species.bounding_radius * pl.scale, species.center_height * pl.scale});
            world.emplace<plant_instance>(e, {static_cast<species_id>(species_index), pl.tint, pl.seed});
            world.emplace<lod_state>(e);
            world.emplace<point_prefix>(e);
            world.emplace<fade_alpha>(e);
            ++spawned;
        }
    }
    world.align<world_transform, bounds, plant_instance, lod_state, point_prefix, fade_alpha>();
    return spawned;
}

void spawn_viewer_and_sky(ecs::world& world, const scenario& s) {
    const ecs::entity viewer = world.create();
    camera cam;
    cam.aspect = float(s.width) / float(s.height);
    cam.viewport_height_px = float(s.height);
    cam.near_plane = s.camera.near_m;
    cam.far_plane = s.camera.far_m;
    cam.lod_scale = s.camera.lod_scale;
    world.emplace<camera>(viewer, cam);

    const ecs::entity sky = world.create();
    world.emplace<sun>(sky);
    environment env;
    env.turbidity = s.sun.turbidity;
    env.sky_intensity = s.sun.sky_intensity;
    env.sky_revision = 0;  // update_sun sets the first revision
    world.emplace<environment>(sky, env);
}

}  // namespace

spawn_report spawn_scenario(ecs::world& world, const scenario& s, const scene_assets& assets) {
    spawn_report report;
    for (const auto& pop : s.populations) report.requested += pop.count;
    spawn_viewer_and_sky(world, s);
    report.plants = spawn_plants(world, s, assets);

    world.set_resource(playback_clock{0, s.fps});
    world.set_resource(camera_track{resolve_camera_keys(s, assets.terrain), true});
    sun_track sun_path;
    for (const auto& k : s.sun.keyframes) sun_path.keys.push_back({k.t, k.elevation_deg, k.azimuth_deg});
    sun_path.intensity = s.sun.intensity;
    world.set_resource(std::move(sun_path));
    world.set_resource(assets.library);
    shadow_settings shadows = s.shadows;
    if (!s.render.shadows) shadows.cascades = 0;
    world.set_resource(shadows);
    world.set_resource(cascade_set{});
    world.set_resource(draw_list{});
    world.set_resource(frame_stats{});
    return report;
}

}  // namespace sylva
