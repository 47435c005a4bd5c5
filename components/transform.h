#pragma once
// World placement of an entity. Positions are double precision so a landscape kilometres from
// the origin keeps millimetre accuracy; rendering subtracts the camera position in double and
// only then converts to float (camera-relative rendering).
// Writer: population spawning (scenario player); read by cull and build_draw_list.
#include <glm/vec3.hpp>

namespace sylva {

struct world_transform {
    glm::dvec3 position{0.0};  // metres, y up
    float yaw = 0.0f;          // radians about +y
    float scale = 1.0f;        // uniform
};
static_assert(sizeof(world_transform) == 32);

}  // namespace sylva
