#pragma once
// Everything a scenario needs drawn, built once on the CPU before the frame loop: the meshes
// (index = mesh id, used in sort keys), per-species textures (index = texture array layer), the
// terrain, and the species table the per-frame systems read as a resource.
#include <cstdint>
#include <string>
#include <vector>

#include "components/lod_state.h"
#include "models/image.h"
#include "models/mesh.h"
#include "models/terrain.h"

namespace sylva {

// One species as the LOD systems see it. Sizes are for scale 1; instances multiply.
struct species_entry {
    std::string name;
    std::uint16_t mesh_full = 0;
    std::uint16_t mesh_reduced = 0;
    std::uint16_t mesh_far = 0;
    std::uint16_t mesh_billboard = 0;  // the crossed billboard's two quads (material billboard)
    std::uint32_t triangles_full = 0;
    std::uint32_t triangles_reduced = 0;
    std::uint32_t triangles_far = 0;
    std::uint32_t triangles_billboard = 0;
    float reduced_distance_m = 60.0f;  // beyond this (times scale and lod_scale): reduced mesh
    float far_distance_m = 200.0f;     // beyond this: far mesh
    float max_distance_m = 1500.0f;    // beyond this: not drawn
    float bounding_radius = 1.0f;      // sphere around the model, unit scale
    float center_height = 0.5f;        // sphere centre above the base, unit scale
    float texture_layer = 0.0f;  // layer of leaf, bark and billboard texture arrays
};

// What the per-frame systems need to know about a mesh id (for statistics).
struct mesh_info {
    std::uint32_t triangles = 0;
    representation drawn_as = representation::none;
};

// The species table as an ECS resource (read by select_representation and build_draw_list).
struct species_library {
    std::vector<species_entry> species;
    std::vector<mesh_info> meshes;  // indexed by mesh id
};

struct scene_assets {
    std::vector<mesh_data> meshes;
    std::vector<image_rgba8> leaf_textures;  // one layer per species, same size
    std::vector<image_rgba8> bark_textures;
    // The crossed billboards' atlases (models/crossed_billboard.h), one layer per species in the
    // order of leaf_textures, all the same size; the normal atlas holds model-space normals.
    std::vector<image_rgba8> billboard_albedo;
    std::vector<image_rgba8> billboard_normal;
    image_rgba8 ground_texture;
    std::vector<std::uint16_t> terrain_meshes;  // the ground in tiles, culled one by one
    float ground_uv_scale_m = 4.0f;
    heightfield terrain;
    species_library library;
    std::uint64_t source_triangles = 0;  // sum over instances of full-detail triangles
};

}  // namespace sylva
