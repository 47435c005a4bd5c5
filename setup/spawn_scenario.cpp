#include "setup/spawn_scenario.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
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
#include "io/input_file.h"
#include "lighting/environment_map.h"
#include "lighting/shadow_cascades.h"
#include "lighting/transfer_rotation.h"
#include "lod/eco_tiles.h"
#include "lod/ground_grid.h"
#include "lod/shell_levels.h"
#include "lod/shell_slanting.h"
#include "models/bake/lodf_leaves.h"
#include "models/generate/textures.h"
#include "models/image/image_ops.h"
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
#include "setup/point_line_assets.h"
#include "setup/shell_assets.h"
#include "setup/species_models.h"
#include "setup/wang_populations.h"

namespace sylva {
namespace {

// A scenario's placement warning once per process: the bench and the tests build many players
// from one scenario, and each would repeat it word for word.
void warn_once(const std::string& message) {
    static std::mutex mutex;
    static std::set<std::string> said;
    const std::lock_guard lock(mutex);
    if (said.insert(message).second) spdlog::warn("{}", message);
}

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

void scale_mesh(mesh_data& mesh, float scale) {
    for (auto& v : mesh.vertices) v.position *= scale;
    for (auto& leaf : mesh.leaves) {
        leaf.center *= scale;
        leaf.size *= scale;
    }
    mesh.bounds_min *= scale;
    mesh.bounds_max *= scale;
}

// Bounding sphere of a mesh standing on its origin: centre on the y axis at mid height.
void fit_bounds(const mesh_data& mesh, species_entry& entry) {
    entry.center_height = 0.5f * (mesh.bounds_min.y + mesh.bounds_max.y);
    const glm::vec3 center{0.0f, entry.center_height, 0.0f};
    float radius = 0.0f;
    for (const auto& v : mesh.vertices) radius = std::max(radius, glm::length(v.position - center));
    entry.bounding_radius = radius;
}

void add_mesh(scene_assets& assets, mesh_data mesh, representation drawn_as, std::uint16_t& id,
              std::uint32_t& triangles) {
    id = std::uint16_t(assets.meshes.size());
    triangles = std::uint32_t(mesh.triangle_count());
    assets.library.meshes.push_back({triangles, drawn_as});
    assets.meshes.push_back(std::move(mesh));
}

// Texture array layers must share a size: small plants' atlases (512 x 256) are replicated to
// the trees' (1024 x 512). The bake sizes them all 2:1 by powers of two, so the factor is an
// integer; anything else is a bake this runtime does not know.
void match_cloud_atlas_sizes(std::vector<image_rgba8>& pages) {
    std::uint32_t width = 0, height = 0;
    for (const auto& page : pages) {
        width = std::max(width, page.width);
        height = std::max(height, page.height);
    }
    for (auto& page : pages) {
        const std::uint32_t factor = page.width ? width / page.width : 0;
        if (factor == 0 || page.width * factor != width || page.height * factor != height)
            throw std::runtime_error("billboard cloud atlas " + std::to_string(page.width) + "x" +
                                     std::to_string(page.height) + " is not an integer scale of the largest (" +
                                     std::to_string(width) + "x" + std::to_string(height) + ")");
        if (factor > 1) page = replicate_upsample(page, factor);
    }
}

// The radius of a sphere about the species' centre (fit_bounds) around every vertex of every
// representation it may draw: shaders/transfer.glsl looks shadows up outside it.
float transfer_radius(const species_entry& entry, std::initializer_list<const mesh_data*> meshes) {
    const glm::vec3 center{0.0f, entry.center_height, 0.0f};
    float radius = entry.bounding_radius;
    for (const mesh_data* mesh : meshes)
        for (const vertex& v : mesh->vertices)
            radius = std::max(radius, glm::length(v.position - center));
    return radius;
}

// Reads a file the scenario names (field `pointer`, a JSON Pointer); a file that cannot be used
// is bad input: a scenario_error naming the scenario, the field, the file and the problem,
// thrown before any output exists. Only `Error` is converted: the bake cache's own disk errors
// stay runtime failures.
template <class Error, class Load>
auto read_named_file(const scenario& s, const std::string& pointer, const std::string& file,
                     const Load& load) -> decltype(load()) {
    try {
        return load();
    } catch (const scenario_error&) {
        throw;
    } catch (const Error& e) {
        throw scenario_error(s.source, pointer, nlohmann::json(file).dump(), e.what());
    }
}

void add_species(scene_assets& assets, const scenario& s, std::size_t index, bake_cache* cache,
                 const scene_needs& needs, const bake_progress& progress) {
    const species_settings settings = resolved_species(s, s.species[index]);
    // Five steps a species: its model (with Luft 2007 baked in), points and lines, transfer,
    // crossed billboard, cloud; most are cache reads.
    const auto step = [&](int done, const char* what) {
        if (progress)
            progress((float(index) + float(done) / 5.0f) / float(s.species.size()), settings.name + ": " + what);
    };
    step(0, "model");
    const std::size_t first_mesh = assets.meshes.size();
    const std::uint64_t seed = species_seed_of(s.seed, index);
    plant_model model =
        read_named_file<input_error>(s, "/species/" + std::to_string(index) + "/model", settings.model,
                                     [&] { return load_species_model(settings, seed, cache); });
    step(1, "points and lines");
    point_line_model point_lines;
    if (needs.point_lines) point_lines = load_species_point_lines(settings, seed, model, cache);
    step(2, "radiance transfer");
    // Behrendt 2005 §4: the transfer of every representation, baked from the full plant (the
    // bake's receivers are unscaled too: transfer does not change with a uniform scale).
    const lighting_variant lighting = lighting_variant_of(settings);
    const bool by_transfer = uses_transfer(lighting);
    transfer_settings transfer_config;
    transfer_config.bands = s.lod.sh_bands;
    transfer_config.seed = seed;
    transfer_config.interreflection = s.lod.sh_interreflection;
    std::array<radiance_transfer, 3> transfer;
    point_line_transfer sample_transfer;
    if (by_transfer) {
        transfer = load_species_transfer(settings, seed, model, transfer_config, cache);
        if (needs.point_lines)
            sample_transfer = load_species_point_line_transfer(settings, seed, model, point_lines,
                                                               transfer_config, cache);
    }
    const std::uint64_t transfer_key =
        by_transfer ? species_transfer_key(settings, seed, transfer_config) : 0;
    const radiance_transfer* full_transfer = by_transfer ? &transfer[0] : nullptr;
    step(3, "crossed billboard");
    // Baked from the unscaled model, so the cache entries do not depend on height_m.
    crossed_billboard billboard =
        load_species_billboard(settings, seed, model, cache, full_transfer, transfer_key);
    lodf_model lodf;
    if (needs.lodf) lodf = load_species_lodf(settings, seed, model, cache);
    step(4, "billboard cloud");
    billboard_cloud cloud;
    if (needs.billboard_clouds)
        cloud =
            load_species_billboard_cloud(settings, seed, model, cache, full_transfer, transfer_key);
    if (by_transfer)
        for (std::size_t k = 0; k < model.lods.size(); ++k)
            model.lods[k].transfer = pack_transfer(transfer[k]);
    // Every species is scaled to the scenario's height_m, generated or imported alike; the
    // billboard quads with it (their textures are scale-free).
    const float natural_height = model.lods[0].bounds_max.y;
    const float scale = settings.height_m / std::max(natural_height, 1e-3f);
    // Luft 2007: the species' field as its plants carry it, for the population's darkening (§5,
    // setup/population_ambient.h) and the viewer's tuning panel (the values the bake derived).
    if (bakes_implicit(settings)) {
        assets.densities.resize(s.species.size());
        assets.densities[index] =
            species_density_of(model, implicit_settings_of(settings, seed), scale, settings.implicit.population);
    } else if (settings.implicit.population) {
        warn_once(fmt::format("species {} ({}): implicit.population has no effect under lighting \"{}\"; it needs "
                              "\"implicit\" or \"sh_implicit\"",
                              index, settings.name, settings.lighting));
    }
    for (auto& lod : model.lods) scale_mesh(lod, scale);
    scale_mesh(billboard.mesh, scale);
    scale_mesh(cloud.mesh, scale);
    // The bake labels cloud quads like crossed billboards; the renderer draws them apart
    // (one-sided, distance-threshold fade).
    for (auto& sub : cloud.mesh.submeshes) sub.material = material_kind::billboard_cloud;

    species_entry entry;
    entry.name = settings.name;
    entry.reduced_distance_m = settings.reduced_distance_m;
    entry.far_distance_m = settings.far_distance_m;
    entry.max_distance_m = settings.max_distance_m;
    entry.texture_layer = float(index);
    fit_bounds(model.lods[0], entry);
    if (by_transfer) {
        entry.transfer_radius =
            transfer_radius(entry, {&model.lods[1], &model.lods[2], &billboard.mesh, &cloud.mesh});
        entry.transfer_layer = float(assets.billboard_transfer.size());
        for (image_rgba8& page : billboard.transfer_pages)
            assets.billboard_transfer.push_back(std::move(page));
        for (image_rgba8& page : cloud.transfer_pages)
            assets.cloud_transfer.push_back(std::move(page));
    }
    // Rebollo 2006: LoDF's trunk and foliage as index lists over the full mesh's vertices.
    mesh_data lodf_bark, lodf_foliage;
    if (lodf.structure.leaf_count > 0) {
        lodf_bark = non_foliage_part(model.lods[0], false);
        lodf_foliage.indices = std::move(lodf.indices);
        lodf_foliage.submeshes.push_back({0, std::uint32_t(lodf_foliage.indices.size()), material_kind::leaf});
        lodf_foliage.bounds_min = model.lods[0].bounds_min;
        lodf_foliage.bounds_max = model.lods[0].bounds_max;
    }
    add_mesh(assets, std::move(model.lods[0]), representation::mesh_full, entry.mesh_full, entry.triangles_full);
    if (lodf.structure.leaf_count > 0) {
        std::uint32_t triangles = 0;
        add_mesh(assets, std::move(lodf_bark), representation::lodf, entry.mesh_lodf_bark, triangles);
        assets.library.meshes.back().vertices_of = entry.mesh_full;
        add_mesh(assets, std::move(lodf_foliage), representation::lodf, entry.mesh_lodf_foliage, triangles);
        assets.library.meshes.back().vertices_of = entry.mesh_full;
        entry.lodf_clusters = std::uint32_t(lodf.structure.clusters.size());
        entry.lodf_leaves = lodf.structure.leaf_count;
        assets.library.lodf.resize(s.species.size());
        assets.library.lodf[index] = std::move(lodf.structure);
    }
    add_mesh(assets, std::move(model.lods[1]), representation::mesh_reduced, entry.mesh_reduced,
             entry.triangles_reduced);
    add_mesh(assets, std::move(model.lods[2]), representation::mesh_far, entry.mesh_far, entry.triangles_far);
    if (needs.facing_billboards) {
        std::uint32_t triangles = 0;
        add_mesh(assets, facing_billboard_mesh(billboard.mesh), representation::facing_billboard, entry.mesh_facing,
                 triangles);
    }
    add_mesh(assets, std::move(billboard.mesh), representation::crossed_billboard, entry.mesh_billboard,
             entry.triangles_billboard);
    if (needs.point_lines) {
        point_line_records records;
        if (by_transfer) {
            // model.triangles keeps the full mesh's vertex array (models/bake/point_line_model.h).
            if (point_lines.triangles.vertices.size() != transfer[0].receiver_count())
                throw std::logic_error(
                    "species '" + settings.name +
                    "': the point/line triangles do not share the full mesh's vertices");
            records = {pack_transfer(transfer[0]), pack_transfer(sample_transfer.points),
                       pack_transfer(sample_transfer.lines)};
        }
        add_point_line_parts(assets, entry, point_lines, scale, settings.importance,
                             by_transfer ? &records : nullptr);
    }
    if (needs.billboard_clouds) {
        add_mesh(assets, std::move(cloud.mesh), representation::billboard_cloud, entry.mesh_cloud,
                 entry.triangles_cloud);
        assets.cloud_albedo.push_back(std::move(cloud.pages[std::size_t(cloud_atlas_page::albedo)]));
        assets.cloud_normal.push_back(std::move(cloud.pages[std::size_t(cloud_atlas_page::normal)]));
        assets.cloud_pre_lit.push_back(std::move(cloud.pages[std::size_t(cloud_atlas_page::pre_lit)]));
    }
    entry.lighting = lighting;
    for (std::size_t m = first_mesh; m < assets.meshes.size(); ++m)
        assets.library.meshes[m].lighting = entry.lighting;
    assets.leaf_textures.push_back(std::move(model.leaf_texture));
    assets.bark_textures.push_back(std::move(model.bark_texture));
    assets.billboard_albedo.push_back(std::move(billboard.albedo));
    assets.billboard_normal.push_back(std::move(billboard.normal));
    assets.library.species.push_back(std::move(entry));
}

// The ground's coarser grids and every grid's skirts (resources/scene_assets.h terrain_grids),
// the skirts as deep as lod/ground_grid.h ground_skirt_depths says. Skipped, with a warning,
// where the meshes would not fit 16-bit mesh ids (the ground is then drawn on its own samples at
// every distance).
void add_ground_grids(scene_assets& assets, std::uint32_t tiles_per_side) {
    const std::uint32_t cells = assets.terrain.resolution - 1;
    const std::uint32_t tiles =
        std::clamp(tiles_per_side, 1u, cells);  // as terrain_tile_meshes clamps
    const std::size_t grids = ground_grid_count(cells / tiles);
    const std::size_t count = assets.terrain_meshes.size();
    if (assets.meshes.size() + (2 * grids - 1) * count >= assets.k_no_skirt) {
        spdlog::warn(
            "terrain: {} tiles on {} grids need more meshes than 16-bit ids hold; the ground keeps "
            "its finest grid at every distance",
            count, grids);
        return;
    }
    for (std::size_t g = 0; g < grids; ++g)
        assets.terrain_grid_errors.push_back(
            g == 0 ? std::vector<float>(count, 0.0f)
                   : terrain_tile_errors(assets.terrain, tiles, 1u << g));
    auto add = [&](mesh_data&& mesh) {
        if (mesh.indices.empty()) return scene_assets::k_no_skirt;
        const auto id = std::uint16_t(assets.meshes.size());
        assets.library.meshes.push_back(
            {std::uint32_t(mesh.triangle_count()), representation::none});
        assets.meshes.push_back(std::move(mesh));
        return id;
    };
    for (std::size_t g = 0; g < grids; ++g) {
        const auto stride = std::uint32_t(1u << g);
        if (g == 0) {
            assets.terrain_grids.push_back(assets.terrain_meshes);
        } else {
            std::vector<std::uint16_t>& ids = assets.terrain_grids.emplace_back();
            for (mesh_data& tile : terrain_tile_meshes(assets.terrain, tiles, 1.0f, stride))
                ids.push_back(add(std::move(tile)));
        }
        const std::vector<float> depths = ground_skirt_depths(
            assets.terrain_grid_errors[g], assets.terrain_grid_errors.back(), tiles);
        std::vector<std::uint16_t>& skirts = assets.terrain_skirts.emplace_back();
        for (mesh_data& skirt : terrain_tile_skirts(assets.terrain, tiles, 1.0f, stride, depths))
            skirts.push_back(add(std::move(skirt)));
    }
}

}  // namespace

scene_assets build_scene_assets(const scenario& s, bake_cache* cache, const scene_needs& needs,
                                const bake_progress& progress) {
    scene_assets assets;
    const terrain_settings& t = s.terrain;
    assets.terrain =
        t.heightmap.empty()
            ? generate_terrain(t.size_m, t.resolution, t.height_m, t.octaves, t.frequency, t.seed)
            : read_named_file<std::runtime_error>(s, "/terrain/heightmap", t.heightmap, [&] {
                  return load_heightmap(t.heightmap, t.size_m, t.height_m);
              });
    // uv in metres; the ground shader divides by ground_uv_scale_m (the texture's size on the ground).
    for (mesh_data& tile : terrain_tile_meshes(assets.terrain, t.tiles_per_side, 1.0f)) {
        assets.terrain_meshes.push_back(std::uint16_t(assets.meshes.size()));
        assets.library.meshes.push_back({std::uint32_t(tile.triangle_count()), representation::none});
        assets.meshes.push_back(std::move(tile));
    }
    add_ground_grids(assets, t.tiles_per_side);
    assets.ground_texture = tint(generate_ground_texture(k_texture_size), t.ground_color);
    if (!s.environment.map.empty()) {
        const environment_map map = read_named_file<std::runtime_error>(
            s, "/environment/map", s.environment.map,
            [&] { return load_environment_map(s.environment.map); });
        if (map.sanitised_texels > 0)
            spdlog::warn("environment map {}: {} texels were NaN, infinite or negative; set to 0",
                         s.environment.map, map.sanitised_texels);
        assets.environment_map_sh = project_environment_map(map).c;
        assets.environment_sky =
            downsample_environment_map(map, k_environment_sky_width, k_environment_sky_width / 2);
    }
    for (std::size_t i = 0; i < s.species.size(); ++i) add_species(assets, s, i, cache, needs, progress);
    if (progress) progress(1.0f, "done");
    match_cloud_atlas_sizes(assets.cloud_albedo);
    match_cloud_atlas_sizes(assets.cloud_normal);
    match_cloud_atlas_sizes(assets.cloud_pre_lit);
    match_cloud_atlas_sizes(assets.cloud_transfer);
    if (needs.shells) {
        if (progress) progress(1.0f, "shell textures");
        assets.shells = build_shell_assets(s, assets, cache);
    }
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
