#pragma once
// Turns a scenario into something to draw, CPU only: the terrain and its ground grids, the
// ground texture, the environment map's SH, and every species' representations (generated or
// imported, baked or read from the bake cache), as one scene_assets for the GL scene and for
// spawn_scenario (setup/spawn_scenario.h).
#include <functional>
#include <string>

#include "models/cache/bake_cache.h"
#include "resources/scene_assets.h"
#include "scenarios/scenario.h"

namespace sylva {

// What a scene bakes beyond the mesh levels and crossed billboards: only what its LOD policy
// can select (DESIGN §2, "skip what a scene doesn't need").
struct scene_needs {
    bool point_lines = false;  // Deussen 2002 points and lines (setup/point_line_assets.h)
    bool billboard_clouds =
        false;          // Behrendt 2005 billboard clouds (models/bake/billboard_cloud.h)
    bool lodf = false;  // Rebollo 2006 LoDF foliage (models/bake/lodf_bake.h)
    bool shells =
        false;  // Behrendt 2005 §3 shell textures of the Wang tiles (setup/shell_assets.h)
    // The crossed billboard with one quad turned to the eye (representation::facing_billboard): no
    // bake of its own, but its mesh and programs only when a ladder can choose it.
    bool facing_billboards = false;
};

// Called as the species are baked (or read from the cache): the share done, 0..1, and the step.
using bake_progress = std::function<void(float done, const std::string& step)>;

// `cache` may be null: species models are then generated or imported every time.
scene_assets build_scene_assets(const scenario& s, bake_cache* cache, const scene_needs& needs = {},
                                const bake_progress& progress = {});

}  // namespace sylva
