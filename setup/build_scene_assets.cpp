#include "setup/build_scene_assets.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

#include "io/input_file.h"
#include "lighting/environment_map.h"
#include "lighting/transfer_rotation.h"
#include "lod/ground_grid.h"
#include "models/bake/lodf_leaves.h"
#include "models/generate/textures.h"
#include "models/image/image_ops.h"
#include "models/terrain/terrain.h"
#include "scenarios/scenario_loader.h"
#include "scenarios/species_lookup.h"
#include "setup/point_line_assets.h"
#include "setup/population_ambient.h"
#include "setup/scenario_input.h"
#include "setup/shell_assets.h"
#include "setup/species_models.h"

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
                                     std::to_string(page.height) +
                                     " is not an integer scale of the largest (" +
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

void add_species(scene_assets& assets, const scenario& s, std::size_t index, bake_cache* cache,
                 const scene_needs& needs, const bake_progress& progress) {
    const species_settings settings = resolved_species(s, s.species[index]);
    // Five steps a species: its model (with Luft 2007 baked in), points and lines, transfer,
    // crossed billboard, cloud; most are cache reads.
    const auto step = [&](int done, const char* what) {
        if (progress)
            progress((float(index) + float(done) / 5.0f) / float(s.species.size()),
                     settings.name + ": " + what);
    };
    step(0, "model");
    const std::size_t first_mesh = assets.meshes.size();
    const std::uint64_t seed = species_seed_of(s.seed, index);
    plant_model model = read_named_file<input_error>(
        s, "/species/" + std::to_string(index) + "/model", settings.model,
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
        assets.densities[index] = species_density_of(model, implicit_settings_of(settings, seed),
                                                     scale, settings.implicit.population);
    } else if (settings.implicit.population) {
        warn_once(fmt::format(
            "species {} ({}): implicit.population has no effect under lighting \"{}\"; it needs "
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
        lodf_foliage.submeshes.push_back(
            {0, std::uint32_t(lodf_foliage.indices.size()), material_kind::leaf});
        lodf_foliage.bounds_min = model.lods[0].bounds_min;
        lodf_foliage.bounds_max = model.lods[0].bounds_max;
    }
    add_mesh(assets, std::move(model.lods[0]), representation::mesh_full, entry.mesh_full,
             entry.triangles_full);
    if (lodf.structure.leaf_count > 0) {
        std::uint32_t triangles = 0;
        add_mesh(assets, std::move(lodf_bark), representation::lodf, entry.mesh_lodf_bark,
                 triangles);
        assets.library.meshes.back().vertices_of = entry.mesh_full;
        add_mesh(assets, std::move(lodf_foliage), representation::lodf, entry.mesh_lodf_foliage,
                 triangles);
        assets.library.meshes.back().vertices_of = entry.mesh_full;
        entry.lodf_clusters = std::uint32_t(lodf.structure.clusters.size());
        entry.lodf_leaves = lodf.structure.leaf_count;
        assets.library.lodf.resize(s.species.size());
        assets.library.lodf[index] = std::move(lodf.structure);
    }
    add_mesh(assets, std::move(model.lods[1]), representation::mesh_reduced, entry.mesh_reduced,
             entry.triangles_reduced);
    add_mesh(assets, std::move(model.lods[2]), representation::mesh_far, entry.mesh_far,
             entry.triangles_far);
    if (needs.facing_billboards) {
        std::uint32_t triangles = 0;
        add_mesh(assets, facing_billboard_mesh(billboard.mesh), representation::facing_billboard,
                 entry.mesh_facing, triangles);
    }
    add_mesh(assets, std::move(billboard.mesh), representation::crossed_billboard,
             entry.mesh_billboard, entry.triangles_billboard);
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
        assets.cloud_albedo.push_back(
            std::move(cloud.pages[std::size_t(cloud_atlas_page::albedo)]));
        assets.cloud_normal.push_back(
            std::move(cloud.pages[std::size_t(cloud_atlas_page::normal)]));
        assets.cloud_pre_lit.push_back(
            std::move(cloud.pages[std::size_t(cloud_atlas_page::pre_lit)]));
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
    // uv in metres; the ground shader divides by ground_uv_scale_m (the texture's size on the
    // ground).
    for (mesh_data& tile : terrain_tile_meshes(assets.terrain, t.tiles_per_side, 1.0f)) {
        assets.terrain_meshes.push_back(std::uint16_t(assets.meshes.size()));
        assets.library.meshes.push_back(
            {std::uint32_t(tile.triangle_count()), representation::none});
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
    for (std::size_t i = 0; i < s.species.size(); ++i)
        add_species(assets, s, i, cache, needs, progress);
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

}  // namespace sylva
