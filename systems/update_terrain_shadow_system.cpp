#include "systems/update_terrain_shadow_system.h"

#include <algorithm>

#include "lighting/terrain_shadow.h"

namespace sylva {

void update_terrain_shadow(terrain_shadow& shadow, glm::vec3 towards_sun) {
    terrain_shadow_heights(shadow.heights, shadow.resolution, shadow.spacing(), towards_sun,
                           shadow.shadow_heights);
    shadow.texels.resize(shadow.heights.size() * 2);
    float deepest = 0.0f;
    for (std::size_t i = 0; i < shadow.heights.size(); ++i) {
        const float depth = shadow.shadow_heights[i] - shadow.heights[i];
        shadow.texels[2 * i] = shadow.heights[i];
        shadow.texels[2 * i + 1] = depth;
        deepest = std::max(deepest, depth);
    }
    shadow.deepest_m = deepest;
    shadow.sun_direction = towards_sun;
    ++shadow.revision;
}

void update_terrain_shadow_system::run(ecs::system_context<update_terrain_shadow_system>& ctx) {
    const terrain_shadow* present = ctx.try_resource<terrain_shadow>();
    if (!present || present->resolution < 2) return;
    const glm::vec3 towards_sun = ctx.single<sun>().direction;
    if (present->revision != 0 && present->sun_direction == towards_sun) return;
    update_terrain_shadow(ctx.resource_mut<terrain_shadow>(), towards_sun);
}

}  // namespace sylva
