#include "lod/shell_slanting.h"

#include <glm/geometric.hpp>
#include <limits>

namespace sylva {

float slant_shift_exact(const glm::vec3& vertex, const glm::vec3& centre, const glm::vec3& viewer) {
    const glm::vec3 v = viewer - centre;
    const float along = glm::dot(v, centre - vertex);
    if (v.y == 0.0f) return along == 0.0f ? 0.0f : std::numeric_limits<float>::infinity() * (along > 0 ? 1.0f : -1.0f);
    return along / v.y;
}

float slant_shift(const glm::vec3& vertex, const glm::vec3& centre, const glm::vec3& viewer, float f) {
    const glm::vec3 v = viewer - centre;
    const float length = glm::length(v);
    if (!(length > 0.0f)) return 0.0f;
    return f * glm::dot(v, centre - vertex) / length;
}

}  // namespace sylva
