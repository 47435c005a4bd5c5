#pragma once
// Remakes the terrain's shadow heights (resources/terrain_shadow.h, lighting/terrain_shadow.h)
// when the sun has moved since they were made; a still sun costs a comparison per frame.
// Nothing when the scene has no terrain_shadow resource (no terrain, or built by hand).
#include "components/sun.h"
#include "ecs/system.h"
#include "resources/terrain_shadow.h"

namespace sylva {

// The work of the system on plain data: fills shadow.texels (height, shadow depth) and
// shadow.deepest_m for `towards_sun`, counts the revision up. Allocates only the first time.
void update_terrain_shadow(terrain_shadow& shadow, glm::vec3 towards_sun);

struct update_terrain_shadow_system {
    static constexpr std::string_view k_name = "update_terrain_shadow";
    static constexpr ecs::phase k_phase = ecs::phase::lighting;
    using reads = ecs::reads<sun>;
    using writes = ecs::writes<terrain_shadow>;
    static void run(ecs::system_context<update_terrain_shadow_system>& ctx);
};

}  // namespace sylva
