#pragma once
// Cascaded shadow maps for the sun: split the view frustum (Zhang et al. 2006, parallel-split
// shadow maps, "practical" split scheme) and fit one orthographic light projection per split.
// Each fit is a bounding sphere of the sub-frustum, so its size does not change when the camera
// turns, and the projection is snapped to whole shadow-map texels in world space, so shadow edges
// do not shimmer when the camera moves (Valient, "Stable Rendering of Cascaded Shadow Maps",
// ShaderX6, 2008).
//
// Space: camera-relative world (the eye at the origin, y up), as the renderer draws. Clip space
// is GL's (x, y, depth all in -1..1, glm defaults); depth -1 is the side towards the sun.
#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace sylva {

constexpr int k_max_cascades = 4;

struct cascade_set {
    int count = 0;
    // camera-relative position -> shadow clip space, per cascade
    std::array<glm::mat4, k_max_cascades> light_view_projection{glm::mat4(1.0f), glm::mat4(1.0f),
                                                                glm::mat4(1.0f), glm::mat4(1.0f)};
    std::array<float, k_max_cascades> split_far{};         // view-space distance where it ends
    std::array<float, k_max_cascades> texel_world_size{};  // metres per shadow-map texel
    // False when the cascade's slice of the view holds no receiver (resources/shadow_receivers.h):
    // nothing is drawn into its map, which no surface samples.
    std::array<bool, k_max_cascades> holds_receivers{true, true, true, true};
};

// Split distances C_0 = near .. C_count = far (Zhang et al. 2006, Eq. 4, the practical scheme):
// C_i = lambda n (f/n)^(i/m) + (1 - lambda) (n + (f - n) i/m), m = count. lambda = 1 is the
// logarithmic split, 0 the uniform one. Entries past `count` repeat `far`. count is clamped to
// 1..k_max_cascades, near to > 0, far to >= near.
std::array<float, k_max_cascades + 1> practical_splits(float near, float far, int count,
                                                       float lambda);

// Fits `count` cascades (0 or less: an empty set) between `near` and `shadow_far`.
// camera_view: camera-relative view matrix (rotation only, the eye at the origin); fov_y in
// radians. map_resolution: texels per side of each cascade's map. caster_extension: metres added
// to each light volume towards the sun, so casters outside the view still cast into it.
// camera_position: the eye in world space; the texel grid is anchored to the world through it,
// which is what keeps shadows still when the camera translates (0 anchors it to the eye).
// Each ortho half-width is the sphere radius plus one texel, so snapping (< 1 texel) never
// pushes the sub-frustum out: texel_world_size = 2 half_width / resolution, half_width = radius
// * resolution / (resolution - 2).
cascade_set fit_cascades(const glm::mat4& camera_view, float fov_y, float aspect, float near,
                         float shadow_far, glm::vec3 sun_dir_towards_sun, int count, float lambda,
                         int map_resolution, float caster_extension,
                         glm::dvec3 camera_position = glm::dvec3(0.0));

// Bounding sphere of the view-space sub-frustum between distances `near` and `far` (centre on
// the view axis at distance `center_distance`). Depends only on the frustum's shape, never on
// the camera's orientation.
struct frustum_sphere {
    float center_distance;
    float radius;
};
frustum_sphere sub_frustum_sphere(float fov_y, float aspect, float near, float far);

// A cascade's light-space box as the caster test needs it.
struct cascade_bounds {
    glm::mat4 light_view_projection{1.0f};
    glm::vec3 radius_scale{1.0f};  // clip-space units per metre along x, y, z
    bool holds_receivers = true;   // cascade_set::holds_receivers: false, nothing casts into it
};
// True when a sphere (camera-relative) may cast into the cascade: inside its x/y extent and
// not behind its far plane (anything towards the sun may cast), and the cascade shades
// something.
bool sphere_overlaps_cascade(const cascade_bounds& cascade, glm::vec3 center, float radius);
cascade_bounds make_cascade_bounds(const glm::mat4& light_view_projection);
// The boxes of `set`'s cascades (those past set.count stay default), each marked as its cascade
// holds receivers or not.
std::array<cascade_bounds, k_max_cascades> cascade_boxes(const cascade_set& set);

}  // namespace sylva
