#pragma once
// Behrendt 2005 §3.1: a Wang tile's vegetation as a stack of 2-D textures. The tile's plants are
// cut into horizontal slabs one slice thick and each slab is rendered orthographically from
// above into one texture: horizontally a filter (the bake's supersampling box, then a Gaussian of
// `blur_texels`), vertically occlusion (within a slab the highest surface wins; between slabs the
// renderer blends the slices bottom first). The textures hold premultiplied colour (§3.3), so a
// slice pyramid (lod/shell_blending.h) can merge them.
//
// Each slab is baked with the billboard rasterizer (models/bake/billboard_bake.h) on a plane
// looking down, keeping only the surfaces whose height lies in the slab; several species are
// baked one by one and composited per texel, the higher surface over the lower, as premultiplied
// colour (c_high + c_low·(1 − α_high)).
//
// Seams: the tile is baked with `margin_texels` around it, blurred, then cropped, so a texel at
// the border is filtered with the plants across it. What lies across it must be given: the
// plants of the neighbouring tiles that reach into the tile or its margin (for Wang tiles, the
// full corner and strip sets the tile's colours fix; models/terrain/wang_tiles.h).
#include <cstdint>
#include <span>
#include <vector>

#include "models/image/image.h"
#include "models/mesh.h"
#include "models/terrain/placement.h"

namespace sylva {

struct shell_bake_settings {
    std::uint32_t texels = 128;      // per side of the tile
    std::uint32_t slices = 16;       // slabs from the ground up
    float height_m = 0.0f;           // the stack's height; 0: the tallest plant's top
    std::uint32_t supersampling = 3;  // s x s subsamples per texel (1..8)
    float blur_texels = 0.5f;        // σ of the horizontal Gaussian, in texels; 0: none
    std::uint32_t margin_texels = 3;  // baked around the tile for the blur, then cropped
};

// One species' model as the bake draws it.
struct shell_species {
    const mesh_data* mesh = nullptr;
    const image_rgba8* leaf_texture = nullptr;
    const image_rgba8* bark_texture = nullptr;
};

// A plant of the tile: its species and its placement in tile coordinates (x, z from the tile's
// (x0, z0) corner; outside [0, T)² for a neighbour's plant that reaches in), standing on y = 0.
struct shell_plant {
    std::uint32_t species = 0;
    placement where;
};

struct shell_stack {
    double tile_size_m = 0.0;
    float slice_height_m = 0.0f;  // slab thickness: slice k covers [k, k + 1) x this above ground
    // Per slice, bottom first, texels x texels, row 0 at z = 0 and column 0 at x = 0:
    // premultiplied colour, linear-in-sRGB-bytes as the plants' textures are.
    std::vector<image_rgba8> colour;
    // Per slice: rgb the normal of the highest covered surface as n·0.5 + 0.5 (straight), a the
    // coverage, for the shell's lighting.
    std::vector<image_rgba8> normal;
};

// Deterministic (the rasterizer is). Throws std::invalid_argument for a species index out of
// range, a missing mesh or texture, or settings out of range.
shell_stack bake_shell_stack(std::span<const shell_species> species, std::span<const shell_plant> plants,
                             double tile_size_m, const shell_bake_settings& settings = {});

// The model's triangles placed as the renderer places an instance: turned by `yaw` about +y
// (x' = c·x + s·z, z' = −s·x + c·z; shaders/instance.glsl), scaled, moved to (x, 0, z).
void append_placed(mesh_data& into, const mesh_data& model, const placement& where);

}  // namespace sylva
