#pragma once
// Behrendt 2005 §3: a scenario's shell textures. Every Wang tile type of the scenario's tiling
// (setup/wang_populations.h) is baked once as a slice stack (models/bake/shell_bake.h) from the
// plants every population with placement "wang_tiles" puts in it and around it (each species'
// reduced mesh, the far field's detail), through the bake cache; the renderer lays the tiles over
// the terrain as the tiling does. When every tiled species is lit by SH transfer, the slices carry
// it too (Behrendt 2005 §4: the shells lit like their plants; scenario shells.lighting). None when
// no population is Wang-tiled.
#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "models/bake/shell_bake.h"
#include "models/cache/bake_cache.h"
#include "resources/scene_assets.h"
#include "resources/shell_textures.h"
#include "scenarios/scenario.h"

namespace sylva {

// The bake's settings for a scenario: 16 slices over the tallest plant, 0.25 m texels (at most
// 256 a tile), 3x3 supersampling, a half-texel Gaussian.
shell_bake_settings shell_bake_settings_of(const scenario& s);

// `cache` may be null. Empty when no population is Wang-tiled.
shell_textures build_shell_assets(const scenario& s, const scene_assets& assets, bake_cache* cache);

}  // namespace sylva
