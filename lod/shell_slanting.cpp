#include "lod/shell_slanting.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <limits>

namespace sylva {

float slant_shift_exact(const glm::vec3& vertex, const glm::vec3& centre, const glm::vec3& viewer) {
    const glm::vec3 v = viewer - centre;
    const float along = glm::dot(v, centre - vertex);
    if (v.y == 0.0f) return along == 0.0f ? 0.0f : std::numeric_limits<float>::infinity() * (along > 0 ? 1.0f : -1.0f);
    return along / v.y;
}

float slant_shift(const glm::vec3& vertex, const glm::vec3& centre, const glm::vec3& viewer, float f, float reach) {
    const glm::vec3 v = viewer - centre;
    const float length = glm::length(v);
    if (!(length > 0.0f)) return 0.0f;
    const float limit = f * reach;
    return std::clamp(f * glm::dot(v, centre - vertex) / length, -limit, limit);
}

float triangle_reach(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 m = (a + b + c) / 3.0f;
    return std::max({glm::length(a - m), glm::length(b - m), glm::length(c - m)});
}

float shell_slant_reach(std::span<const mesh_data> tiles) {
    float reach = 0.0f;
    for (const mesh_data& tile : tiles)
        for (std::size_t k = 0; k + 2 < tile.indices.size(); k += 3)
            reach = std::max(reach, triangle_reach(tile.vertices[tile.indices[k]].position,
                                                   tile.vertices[tile.indices[k + 1]].position,
                                                   tile.vertices[tile.indices[k + 2]].position));
    return reach;
}

}  // namespace sylva
