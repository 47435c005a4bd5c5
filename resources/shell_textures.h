#pragma once
// Behrendt 2005 §3: the scene's shell textures, one slice stack per Wang tile type
// (models/bake/shell_bake.h), and how the tiling lays them over the terrain
// (models/terrain/wang_tiles.h). Baked by setup/shell_assets.h when a ladder reaches the shell
// rung; drawn by the shell pass (systems/render/passes/shell_pass.h).
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "models/bake/shell_bake.h"

namespace sylva {

struct shell_textures {
    double tile_size_m = 0.0;
    std::uint32_t colours = 0;
    std::uint64_t tiling_seed = 0;
    glm::dvec2 origin{0.0};  // lattice corner (0, 0)
    // Where the tiled populations grow, {x0, z0, x1, z1} terrain-local (they share one area): the
    // shells are cut to it, as the placement is.
    std::array<double, 4> area{};
    std::vector<shell_stack> tiles;  // by Wang tile index (models/terrain/wang_tiles.h)
    // Measurement only (scenario shells.blending "standard"): the renderer builds the pyramid and
    // blends with the standard equation (lod/shell_blending.h merge_slices_standard).
    bool standard_blending = false;
    // Every tiled species is lit by Luft 2007's implicit surface (lighting "implicit" or
    // "sh_implicit") and the slices by their normals: those normals carry k_a as their length, as
    // the plants' do (§3.2), and shaders/shell.frag decodes it (IMPLICIT_LIGHTING).
    bool implicit = false;
    bool empty() const { return tiles.empty(); }
};

}  // namespace sylva
