#pragma once
// The scene's textures on the GPU, uploaded once from scene_assets: leaf, bark and ground
// layers, the crossed billboards' and billboard clouds' atlases (colour, normals, pre-lit
// colour, SH transfer pages) and transfer.glsl's species block. The passes bind from here.
#include <cstdint>

#include "resources/scene_assets.h"
#include "systems/render/gl_objects.h"

namespace sylva::render {

struct scene_textures {
    explicit scene_textures(const scene_assets& assets);

    gl_texture leaf;
    gl_texture bark;
    gl_texture ground;
    // The terrain's normals at its own samples (x and z; y is what makes them unit), read by the
    // ground's fragments at their world position (shaders/mesh.frag ground_normal): a coarser
    // ground grid (components/ground_tile.h) is then lit as the terrain's samples light it, not
    // by the few normals of its own vertices. None without a terrain.
    gl_texture ground_normal;
    gl_texture billboard_albedo;    // crossed billboards: colour with coverage alpha
    gl_texture billboard_normal;    // and model-space normals
    gl_texture billboard_transfer;  // SH transfer pages, k_transfer_pages layers per species
    gl_texture cloud_albedo;        // billboard clouds: colour with coverage x gaussian alpha
    gl_texture cloud_normal;        // and model-space normals with coverage alpha
    gl_texture cloud_pre_lit;       // colour lit at bake time (pre-lit species)
    gl_texture cloud_transfer;      // SH transfer pages, k_transfer_pages layers per species
    gl_buffer species_block;        // transfer.glsl species_block: each species' sphere
    std::uint64_t uploaded_bytes = 0;

    static constexpr std::size_t k_max_species_spheres = 64;  // transfer.glsl u_species_sphere
};

}  // namespace sylva::render
