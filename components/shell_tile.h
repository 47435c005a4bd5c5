#pragma once
// Behrendt 2005 §3.3: one terrain tile of the shell layer, an entity per tile of the terrain
// mesh (scene_assets::terrain_meshes order) when the scene has shells. Writer: update_shells
// (systems/update_shells_system.h), every frame, tiles in parallel; read by the submit system,
// whose shell pass draws each tile at its level.
#include <glm/vec3.hpp>

#include "lod/shell_levels.h"

namespace sylva {

struct shell_tile {
    glm::vec3 centre{0.0f};  // terrain-local, of the tile's bounding sphere
    float radius = 0.0f;
    shell_level level;       // the pyramid level its nearest point asks, and the merge
};

}  // namespace sylva
