#include "lod/shell_sampling.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace sylva {

float slab_path(const glm::vec3& view, const glm::vec3& slice_normal) {
    const float across = std::abs(glm::dot(glm::normalize(view), slice_normal));
    const float thickness = std::abs(slice_normal.y);
    if (!(across * k_shell_max_path > thickness)) return k_shell_max_path;
    return thickness / across;
}

float opacity_along(float alpha, float path) {
    return 1.0f - std::pow(1.0f - std::min(alpha, 0.999f), path);
}

glm::vec3 seen_normal(const glm::vec3& from_above, const glm::vec3& view) {
    const float length = glm::length(view);
    return length > 0.0f ? from_above * (std::abs(view.y) / length) : from_above;
}

int footprint_taps(const glm::vec2& dx, const glm::vec2& dy, int max_taps) {
    const float lx = glm::length(dx), ly = glm::length(dy);
    const float ratio = std::max(lx, ly) / std::max(std::min(lx, ly), 1e-6f);
    return int(std::clamp(std::ceil(ratio), 1.0f, float(std::max(max_taps, 1))));
}

}  // namespace sylva
