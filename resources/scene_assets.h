#pragma once
// Everything a scenario needs drawn, built once on the CPU before the frame loop: the meshes
// (index = mesh id, used in sort keys), per-species textures (index = texture array layer), the
// terrain, and the species table the per-frame systems read as a resource.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "components/lod_state.h"
#include "models/image/image.h"
#include "models/mesh.h"
#include "models/bake/implicit_illumination.h"
#include "models/bake/lodf_bake.h"
#include "resources/shell_textures.h"
#include "models/bake/point_line_model.h"
#include "models/terrain/terrain.h"
#include "lighting/environment_map.h"

namespace sylva {

// How a species' plants are lit (scenario `lighting`; Behrendt 2005 §2.3 and §4). The renderer
// draws each variant with its own shader: normal-lit, the clouds' baked pre-lit page, or
// precomputed radiance transfer in every representation.
// `implicit` (Luft 2007) is normal-lit from normals that carry the foliage's implicit surface and
// its ambient coefficient as their length (models/bake/implicit_illumination.h); `sh_implicit`
// is lit by SH transfer baked from those normals, with k_a on the sky's light.
enum class lighting_variant : std::uint8_t { normal_mapped, pre_lit, sh, implicit, sh_implicit };
inline constexpr std::size_t k_lighting_variants = 5;

// Lit by precomputed radiance transfer (Behrendt 2005 §4): the transfer is baked and streamed.
constexpr bool uses_transfer(lighting_variant l) { return l == lighting_variant::sh || l == lighting_variant::sh_implicit; }
// The model's normals carry Luft 2007's realigned directions and k_a.
constexpr bool uses_implicit_normals(lighting_variant l) {
    return l == lighting_variant::implicit || l == lighting_variant::sh_implicit;
}

// One species as the LOD systems see it. Sizes are for scale 1; instances multiply.
struct species_entry {
    std::string name;
    std::uint16_t mesh_full = 0;
    std::uint16_t mesh_reduced = 0;
    std::uint16_t mesh_far = 0;
    std::uint16_t mesh_billboard = 0;  // the crossed billboard's two quads (material billboard)
    std::uint16_t mesh_facing = 0;     // the same pair, one quad turned to the eye (material facing_billboard)
    // The billboard cloud (Behrendt 2005 §2, material billboard_cloud), when the scene's LOD
    // policy can select it; 0 triangles otherwise.
    std::uint16_t mesh_cloud = 0;
    std::uint32_t triangles_full = 0;
    std::uint32_t triangles_reduced = 0;
    std::uint32_t triangles_far = 0;
    std::uint32_t triangles_billboard = 0;
    std::uint32_t triangles_cloud = 0;
    float reduced_distance_m = 60.0f;  // beyond this (times scale and lod_scale): reduced mesh
    float far_distance_m = 200.0f;     // beyond this: far mesh
    float max_distance_m = 1500.0f;    // beyond this: not drawn
    float bounding_radius = 1.0f;      // sphere around the model, unit scale
    float center_height = 0.5f;        // sphere centre above the base, unit scale
    float texture_layer = 0.0f;  // layer of leaf, bark and billboard texture arrays
    lighting_variant lighting = lighting_variant::normal_mapped;
    // Lighting sh: the radius (scale 1, about the same centre) of a sphere around every
    // representation, crossed billboard and cloud included, outside which shadows come from
    // other objects (shaders/transfer.glsl); and the species' first layer in the transfer-page
    // arrays (k_transfer_pages of them; only SH species have pages).
    float transfer_radius = 0.0f;
    float transfer_layer = 0.0f;
    // The point/line representation's parts (species_library::lod_parts), when the scene's
    // LOD policy can select it; none otherwise, and none for a species split into octree cells
    // (Deussen 2002 §6.1), whose parts belong to its cells (species_library::cells).
    std::uint32_t first_lod_part = 0;
    std::uint32_t lod_part_count = 0;
    std::uint32_t first_cell = 0;
    std::uint32_t cell_count = 0;  // > 1: every plant of the species has this many cell entities
    // LoDF (Rebollo 2006), when a ladder reaches it: the full mesh's trunk and branches, and its
    // foliage index list (every leaf of F^r), both over mesh_full's vertices (mesh_info::
    // vertices_of); species_library::lodf[species] is the structure. 0 clusters: none.
    std::uint16_t mesh_lodf_bark = 0;
    std::uint16_t mesh_lodf_foliage = 0;
    std::uint32_t lodf_clusters = 0;
    std::uint32_t lodf_leaves = 0;  // L: F_0's leaves
};

// One octree cell of a split species: its parts in species_library::lod_parts.
struct lod_cell_entry {
    std::uint32_t first_lod_part = 0;
    std::uint32_t lod_part_count = 0;
};

// One part of a species' point/line representation (models/bake/point_line_model.h lod_part),
// scaled to the species' height. Read by update_point_prefix (Deussen 2002 Eq. 1, Eq. 2, §5.3)
// and build_draw_list (which draws its prefixes from the two meshes).
struct lod_part_entry {
    lod_primitive primitive = lod_primitive::points;
    float importance = 1.0f;
    float area_m2 = 0.0f;        // A_p or A_l
    glm::vec3 center{0.0f};      // model space, species scale: r is measured to it
    std::uint32_t triangle_count = 0;   // k
    std::uint32_t primitive_count = 0;  // n_p points or n_l lines
    std::uint32_t first_after = 0;      // into species_library::points_after (points parts)
    float line_length_m = 0.0f;  // l
    float line_error_m = 0.0f;   // ε_l
    std::uint16_t mesh_triangles = 0;   // the part's triangles in random order
    std::uint16_t mesh_primitives = 0;  // its points (reverse order) or lines
    std::uint16_t mesh_splats = 0;      // line parts: the lines' end points as splats (short lines)
};

// What the per-frame systems need to know about a mesh id (for statistics).
struct mesh_info {
    std::uint32_t triangles = 0;  // triangles, points or lines, by `primitive`
    representation drawn_as = representation::none;
    primitive_kind primitive = primitive_kind::triangles;
    lighting_variant lighting = lighting_variant::normal_mapped;  // its species' (terrain: normal)
    // An index list over another mesh's vertices (LoDF: no vertices of its own, Eq. 3): that
    // mesh's id; -1 for a mesh with its own vertices.
    std::int32_t vertices_of = -1;
};

// The species table as an ECS resource (read by select_representation and build_draw_list).
struct species_library {
    std::vector<species_entry> species;
    std::vector<mesh_info> meshes;  // indexed by mesh id
    std::vector<lod_part_entry> lod_parts;
    std::vector<lod_cell_entry> cells;
    std::vector<std::uint32_t> points_after;  // lod_part_entry::first_after indexes it
    // Rebollo 2006, by species: each species' LoDF structure when a ladder reaches the lodf rung
    // (species_entry::mesh_lodf_foliage holds its index list; no clusters otherwise); empty
    // when no ladder does.
    std::vector<lodf_structure> lodf;
};

// Width of scene_assets::environment_sky: twice the renderer's 128-texel sky texture, so the
// reduction there still averages a few texels; small enough to keep with the assets.
inline constexpr int k_environment_sky_width = 256;

// An implicit-lit species' density field as its plants carry it (Luft 2007 Eq. 2–4), in model
// space at the species' scale: the bake's generators and settings (models/bake/
// implicit_illumination.h, ρ scaled with the model), and the half size h of the box the
// population factor is stored over (components/population_ambient.h). No generators: the species
// is not implicit-lit and neither darkens nor is darkened.
struct species_density {
    std::vector<glm::vec3> generators;
    implicit_settings used;
    float half_size_m = 1.0f;
    float scale = 1.0f;     // species' height_m over its model's: the bake's ρ is used.rho_m / scale
    bool receives = false;  // species.implicit.population
};

struct scene_assets {
    std::vector<mesh_data> meshes;
    std::vector<image_rgba8> leaf_textures;  // one layer per species, same size
    std::vector<image_rgba8> bark_textures;
    // The crossed billboards' atlases (models/bake/crossed_billboard.h), one layer per species in the
    // order of leaf_textures, all the same size; the normal atlas holds model-space normals.
    std::vector<image_rgba8> billboard_albedo;
    std::vector<image_rgba8> billboard_normal;
    // Their SH transfer pages, laid out as cloud_transfer's.
    std::vector<image_rgba8> billboard_transfer;
    // The billboard clouds' atlas pages (models/bake/billboard_cloud.h: colour with coverage x
    // gaussian alpha, model-space normals with coverage alpha), one layer per species in the same
    // order, all the size of the largest (smaller atlases replicated by an integer factor); empty
    // when the scene draws no clouds.
    std::vector<image_rgba8> cloud_albedo;
    std::vector<image_rgba8> cloud_normal;
    std::vector<image_rgba8> cloud_pre_lit;  // colour lit at bake time, alpha as cloud_albedo's
    // SH transfer pages (models/bake/transfer_pages.h), k_transfer_pages for each species lit by
    // transfer, in species order (species_entry::transfer_layer); empty when no species is.
    std::vector<image_rgba8> cloud_transfer;
    image_rgba8 ground_texture;
    std::vector<std::uint16_t> terrain_meshes;  // the ground in tiles, culled one by one
    // The ground's grids (geometric mip-mapping, lod/ground_grid.h), by grid g then tile (in
    // terrain_meshes order): terrain_grids[g][t] is tile t on every 2^g-th sample (grid 0:
    // terrain_meshes), terrain_skirts[g][t] its skirts there (models/terrain/terrain.h
    // terrain_tile_skirts; k_no_skirt when it has none) and terrain_grid_errors[g][t] how far
    // grid g strays vertically from the terrain. Empty in scenes built by hand: the renderer
    // then draws terrain_meshes.
    static constexpr std::uint16_t k_no_skirt = 0xFFFF;
    std::vector<std::vector<std::uint16_t>> terrain_grids;
    std::vector<std::vector<std::uint16_t>> terrain_skirts;
    std::vector<std::vector<float>> terrain_grid_errors;
    float ground_uv_scale_m = 4.0f;
    heightfield terrain;
    // The scenario's environment map (environment.map), when it names one: its radiance SH as
    // the file lies (spawn_scenario hands it to the environment component), and the map reduced
    // to k_environment_sky_width x half that for the renderer's sky background. Empty otherwise.
    std::array<glm::vec3, 9> environment_map_sh{};
    environment_map environment_sky;
    species_library library;
    std::uint64_t source_triangles = 0;  // sum over instances of full-detail triangles
    // Luft 2007, by species: each implicit-lit species' field (others have no generators), for
    // the population's darkening (§5, setup/population_ambient.h) and the viewer's tuning panel;
    // empty when no species is implicit-lit.
    std::vector<species_density> densities;
    // Behrendt 2005 §3: the Wang tiles' shell textures, when a ladder reaches the shell rung.
    shell_textures shells;
};

// Whether some implicit-lit species is darkened by its neighbours (species.implicit.population
// on a species with a field): the population bake (setup/population_ambient.h) runs and the
// renderer's programs interpolate the factor only then.
inline bool has_population_receivers(const scene_assets& assets) {
    for (const species_density& d : assets.densities)
        if (d.receives && !d.generators.empty()) return true;
    return false;
}

}  // namespace sylva
