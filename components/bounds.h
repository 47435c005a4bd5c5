#pragma once
// Bounding sphere in world units relative to world_transform::position: centre straight above
// the position at `center_height` (plants grow upward), radius already scaled.
// Writer: population spawning; read by cull and select_representation.
namespace sylva {

struct bounds {
    float radius = 0.0f;
    float center_height = 0.0f;
};
static_assert(sizeof(bounds) == 8);

}  // namespace sylva
