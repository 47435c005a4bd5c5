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
    // Behrendt 2005 §4 on shells: the SH transfer of the highest surface per slice texel, at
    // this many texels per side (a divisor-free box of the colour texels; 0: none). Every
    // species must then carry its transfer (mesh_data::transfer).
    std::uint32_t transfer_texels = 0;
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
    // With shell_bake_settings::transfer_texels, else empty: per slice k_transfer_pages pages
    // (slice-major: slice k's pages at [k·5, k·5 + 5)) of transfer_texels², the world-space
    // transfer of the highest covered surface, its seen side the one facing up, laid out and
    // encoded as models/bake/transfer_pages.h lays out a billboard's; page 4's blue is Luft 2007's
    // k_a of those surfaces (straight 8-bit, 1 for a plain model; it scales the sky's light, as
    // lighting "sh_implicit" does), page 4's alpha the texel's coverage (straight 8-bit), which
    // the slice pyramid weighs merged slices by.
    std::vector<image_rgba8> transfer;
    bool has_transfer() const { return !transfer.empty(); }
};

// The channels of a transfer page set holding the texel's k_a (page 4's blue) and its coverage
// (page 4's alpha): the 18 coefficients fill channels 0..17.
constexpr std::size_t k_shell_transfer_ambient_channel = 18;
constexpr std::size_t k_shell_transfer_coverage_channel = 19;

// Deterministic (the rasterizer is). Throws std::invalid_argument for a species index out of
// range, a missing mesh or texture, settings out of range, or transfer_texels with a species
// whose mesh has no transfer (or more than `texels`).
shell_stack bake_shell_stack(std::span<const shell_species> species, std::span<const shell_plant> plants,
                             double tile_size_m, const shell_bake_settings& settings = {});

// The model's triangles placed as the renderer places an instance: turned by `yaw` about +y
// (x' = c·x + s·z, z' = −s·x + c·z; shaders/instance.glsl), scaled, moved to (x, 0, z). The
// model's transfer, when it has one, is turned with it (lighting/transfer_rotation.h).
void append_placed(mesh_data& into, const mesh_data& model, const placement& where);

}  // namespace sylva
