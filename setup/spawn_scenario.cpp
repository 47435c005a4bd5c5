#include "setup/spawn_scenario.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

#include "components/bounds.h"
#include "components/camera.h"
#include "components/cluster_changes.h"
#include "components/environment.h"
#include "components/fade_alpha.h"
#include "components/ground_tile.h"
#include "components/lod_state.h"
#include "components/octree_cell.h"
#include "components/plant_instance.h"
#include "components/point_prefix.h"
#include "components/shell_tile.h"
#include "components/sun.h"
#include "components/transform.h"
#include "lighting/shadow_cascades.h"
#include "lod/eco_tiles.h"
#include "lod/shell_levels.h"
#include "lod/shell_slanting.h"
#include "models/random.h"
#include "models/terrain/density.h"
#include "models/terrain/placement.h"
#include "models/terrain/terrain.h"
#include "resources/draw_list.h"
#include "resources/frame_stats.h"
#include "resources/ground_lod.h"
#include "resources/lodf_slots.h"
#include "resources/playback.h"
#include "resources/shadow_receivers.h"
#include "resources/shell_view.h"
#include "resources/terrain_shadow.h"
#include "scenarios/scenario_loader.h"
#include "scenarios/species_lookup.h"
#include "setup/scenario_input.h"
#include "setup/wang_populations.h"

namespace sylva {

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

struct planned_plant {
    placement where;
    std::size_t species = 0;
};

// Every population's placements, in population order (deterministic for the scenario seed).
std::vector<planned_plant> plan_plants(const scenario& s, const scene_assets& assets) {
    std::vector<planned_plant> plants;
    for (std::size_t p = 0; p < s.populations.size(); ++p) {
        const population_settings& pop = s.populations[p];
        density_map density;
        if (!pop.density_map.empty())
            density = read_named_file<std::runtime_error>(
                s, "/populations/" + std::to_string(p) + "/density_map", pop.density_map,
                [&] { return load_density_map(pop.density_map); });
        else if (pop.density.enabled)
            density = procedural_density(hash_combine(s.seed, std::uint64_t(p), 0xde45ULL),
                                         pop.density.frequency, pop.density.coverage);
        const placement_rules rules{pop.area,          pop.count,          pop.min_spacing_m,
                                    pop.scale_min,     pop.scale_max,      pop.max_slope_deg,
                                    pop.min_altitude_m, pop.max_altitude_m, pop.placement == "poisson",
                                    density.values.empty() ? nullptr : &density};
        const auto placed = pop.placement == "wang_tiles"
                                ? place_wang_population(s, p, wang_reach_m(s, p, assets))
                                : place_population(assets.terrain, rules, hash_combine(s.seed, std::uint64_t(p), 0x9147ULL));
        // Wang tiles place for the density `count` asks, so a few more or fewer come out.
        const double expected = pop.placement == "wang_tiles" ? 0.9 * double(pop.count) : double(pop.count);
        if (double(placed.size()) < expected)
            warn_once(fmt::format(
                "population {} ({}): placed {} of {} plants (spacing, slope, altitude or "
                "density left no room)",
                p, pop.species, placed.size(), pop.count));
        const std::size_t species = species_index_of(s, pop.species);
        for (const auto& where : placed) plants.push_back({where, species});
    }
    return plants;
}

void create_plant(ecs::world& world, const scenario& s, const scene_assets& assets, const planned_plant& plant) {
    const species_entry& species = assets.library.species.at(plant.species);
    const placement& pl = plant.where;
    const ecs::entity e = world.create();
    const double y = assets.terrain.height_at(pl.xz.x, pl.xz.y);
    world.emplace<world_transform>(e, {glm::dvec3(pl.xz.x, y, pl.xz.y) + s.world_offset, pl.yaw, pl.scale});
    world.emplace<bounds>(e, {species.bounding_radius * pl.scale, species.center_height * pl.scale});
    world.emplace<plant_instance>(e, {static_cast<species_id>(plant.species), pl.tint, pl.seed});
    world.emplace<lod_state>(e);
    world.emplace<point_prefix>(e);
    world.emplace<fade_alpha>(e);
}

// Deussen 2002 §6.1: every plant of a species split into octree cells gets one entity per
// cell, created in plant order after the plant tables are aligned (so `plant` is the dense
// index every plant table shares, and the plant tables stay as culling expects them).
void spawn_octree_cells(ecs::world& world, const species_library& library) {
    const auto& plants = world.table<plant_instance>();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> cells;  // (plant, cell)
    for (std::size_t i = 0; i < plants.size(); ++i) {
        const species_entry& species = library.species[static_cast<std::size_t>(plants.data()[i].species)];
        if (species.cell_count < 2) continue;
        for (std::uint32_t c = 0; c < species.cell_count; ++c) cells.emplace_back(std::uint32_t(i), species.first_cell + c);
    }
    for (const auto& [plant, cell] : cells) {
        const ecs::entity e = world.create();
        world.emplace<octree_cell>(e, {plant, cell});
        world.emplace<cell_prefix>(e);
    }
    if (!cells.empty()) world.align<octree_cell, cell_prefix>();
}

// Deussen 2002 §6.2: with eco tiles on, plants are created tile by tile (each tile's plants a
// contiguous range of the component tables) and the tiles become entities that culling walks.
std::size_t spawn_plants(ecs::world& world, const scenario& s, const scene_assets& assets) {
    const std::vector<planned_plant> plants = plan_plants(s, assets);
    if (!s.eco_tiles.enabled) {
        for (const auto& plant : plants) create_plant(world, s, assets, plant);
    } else {
        std::vector<glm::dvec2> xz;
        xz.reserve(plants.size());
        for (const auto& plant : plants) xz.push_back(plant.where.xz);
        const double half = 0.5 * s.terrain.size_m;
        const eco_tile_tree tree = build_eco_tiles(xz, {-half, -half, half, half}, s.eco_tiles.max_plants_per_tile);
        for (std::uint32_t i : tree.order) create_plant(world, s, assets, plants[i]);
        eco_tile_extent extent{0.0f, 1.0f, s.world_offset};
        for (const auto& pop : s.populations) {
            const species_entry& sp = assets.library.species.at(species_index_of(s, pop.species));
            extent.reach_m = std::max(extent.reach_m, (sp.center_height + sp.bounding_radius) * pop.scale_max);
            extent.max_scale = std::max(extent.max_scale, pop.scale_max);
        }
        create_tile_entities(world, tree, assets.terrain, extent);
    }
    world.align<world_transform, bounds, plant_instance, lod_state, point_prefix, fade_alpha>();
    spawn_octree_cells(world, assets.library);
    spawn_lodf_clusters(world, assets.library, s.lod.lodf_slots);
    return plants.size();
}

void spawn_viewer_and_sky(ecs::world& world, const scenario& s, const scene_assets& assets) {
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
    // The sky is integrated with the sun here and turned to its azimuth, and the map turns
    // with the sun from here (components/environment.h).
    if (!s.sun.keyframes.empty()) env.reference_azimuth_deg = s.sun.keyframes.front().azimuth_deg;
    env.has_map = !s.environment.map.empty();
    env.map_rotation_deg = s.environment.map_rotation_deg;
    env.map_radiance_sh = assets.environment_map_sh;
    world.emplace<environment>(sky, env);
}

}  // namespace

// Behrendt 2005 §3: with shell textures, one shell_tile entity per terrain tile and the shells'
// view; an inactive view otherwise.
void spawn_shells(ecs::world& world, const scenario& s, const scene_assets& assets) {
    shell_view view;
    if (!assets.shells.empty()) {
        view.active = true;
        view.terrain_origin = s.world_offset;
        view.slice_height_m = assets.shells.tiles.front().slice_height_m;
        view.slant = float(s.shells.slant);
        view.half_resolution = s.shells.half_resolution;
        view.max_level = shell_pyramid_levels(std::uint32_t(assets.shells.tiles.front().colour.size())) - 1;
        view.mean_scale.assign(s.species.size(), 1.0f);
        for (std::size_t k = 0; k < s.species.size(); ++k)
            for (const population_settings& p : s.populations)
                if (p.species == s.species[k].name) {
                    view.mean_scale[k] = 0.5f * (p.scale_min + p.scale_max);
                    break;
                }
        const float stack_m = view.slice_height_m * float(assets.shells.tiles.front().colour.size());
        // The slices' grids are the ground's (components/shell_tile.h; add_ground_grids), with
        // each tile's vertical error; the terrain's own alone when it has no coarser ones.
        const std::vector<std::vector<float>>& errors = assets.terrain_grid_errors;
        // The slices rise up to the stack's height and Eq. 2 moves a vertex vertically by at most
        // f times its distance from its triangle's centre on the terrain's own grid, which the
        // shader holds every grid to (shaders/shell.vert; lod/shell_slanting.h).
        float slant_reach = 0.0f;
        for (std::uint16_t id : assets.terrain_meshes)
            slant_reach = std::max(slant_reach, shell_slant_reach(std::span(&assets.meshes.at(id), 1)));
        view.slant_reach_m = slant_reach;
        for (std::size_t t = 0; t < assets.terrain_meshes.size(); ++t) {
            const mesh_data& tile = assets.meshes.at(assets.terrain_meshes[t]);
            shell_tile entity;
            const float lift = view.slant * slant_reach;
            const glm::vec3 top = tile.bounds_max + glm::vec3(0.0f, stack_m + lift, 0.0f);
            const glm::vec3 bottom = tile.bounds_min - glm::vec3(0.0f, lift, 0.0f);
            entity.centre = 0.5f * (bottom + top);
            entity.radius = glm::length(top - entity.centre);
            entity.grids = std::uint8_t(std::max<std::size_t>(1, errors.size()));
            for (std::size_t g = 0; g < errors.size(); ++g) entity.grid_error_m[g] = errors[g].at(t);
            world.emplace<shell_tile>(world.create(), entity);
        }
    }
    world.set_resource(std::move(view));
}

void spawn_ground_tiles(ecs::world& world, const scenario& s, const scene_assets& assets) {
    world.set_resource(ground_lod{float(s.terrain.max_error_px)});
    // The sun's shadow of the ground comes from its heights, not from the shadow cascades
    // (lighting/terrain_shadow.h).
    if (assets.terrain.resolution >= 2) {
        terrain_shadow shadow;
        shadow.resolution = assets.terrain.resolution;
        shadow.size_m = assets.terrain.size_m;
        shadow.heights = assets.terrain.heights;
        world.set_resource(std::move(shadow));
    }
    if (assets.terrain_grids.empty()) return;
    for (std::size_t t = 0; t < assets.terrain_meshes.size(); ++t) {
        const mesh_data& tile = assets.meshes.at(assets.terrain_meshes[t]);
        ground_tile entity;
        const glm::vec3 centre = 0.5f * (tile.bounds_min + tile.bounds_max);
        entity.centre = s.world_offset + glm::dvec3(centre);
        entity.radius = glm::length(tile.bounds_max - centre);
        entity.grids = std::uint8_t(assets.terrain_grids.size());
        for (std::size_t g = 0; g < assets.terrain_grids.size(); ++g)
            entity.grid_error_m[g] = assets.terrain_grid_errors[g][t];
        world.emplace<ground_tile>(world.create(), entity);
    }
}

void spawn_lodf_clusters(ecs::world& world, const species_library& library, std::uint32_t slot_count) {
    lodf_slots slots;
    for (const species_entry& species : library.species)
        slots.clusters_per_slot = std::max(slots.clusters_per_slot, species.lodf_clusters);
    if (slots.clusters_per_slot > 0) {
        slots.slots.resize(slot_count);
        slots.changed.resize(slot_count);
        for (auto& c : slots.changed) c.reserve(slots.clusters_per_slot);
        for (std::size_t i = 0; i < std::size_t(slot_count) * slots.clusters_per_slot; ++i)
            world.emplace<cluster_changes>(world.create());
    }
    world.set_resource(std::move(slots));
}

// Cells per side of the receivers' height grid (resources/shadow_receivers.h): 47 m on landscape's
// 3 km terrain, finer than a near cascade's slice.
constexpr std::uint32_t k_receiver_cells = 64;

spawn_report spawn_scenario(ecs::world& world, const scenario& s, const scene_assets& assets) {
    spawn_report report;
    for (const auto& pop : s.populations) report.requested += pop.count;
    spawn_viewer_and_sky(world, s, assets);
    report.plants = spawn_plants(world, s, assets);
    spawn_shells(world, s, assets);
    spawn_ground_tiles(world, s, assets);
    report.population = bake_population_ambient(world, assets);
    if (report.population.receivers > 0)
        spdlog::info("population ambient (Luft 2007 §5): {} receivers, {} neighbour pairs, {} darkened "
                     "(lowest factor {:.2f}), {:.2f} s",
                     report.population.receivers, report.population.neighbour_pairs, report.population.darkened,
                     report.population.min_factor, report.population.seconds);
    // The receivers' heights for skipping shadow cascades that shade only air: the ground, then
    // every plant's bounding sphere.
    receiver_heights receivers =
        make_receiver_heights(assets.terrain, s.world_offset, k_receiver_cells);
    const auto& transform_table = world.table<world_transform>();
    const auto& bounds_table = world.table<bounds>();  // aligned with the transforms (spawn_plants)
    const world_transform* transforms = transform_table.data();
    const bounds* spheres = bounds_table.data();
    for (std::size_t i = 0; i < std::min(transform_table.size(), bounds_table.size()); ++i) {
        const glm::dvec3 p = transforms[i].position;
        receivers.raise(p.x, p.z, double(spheres[i].radius),
                        float(p.y + spheres[i].center_height + spheres[i].radius));
    }
    world.set_resource(std::move(receivers));

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
