#pragma once
// View-frustum and distance culling of plant instances, in parallel chunks: a plant is visible
// when its bounding sphere touches the camera frustum and it is nearer than its species' draw
// distance; it may cast shadows when it is within the shadow distance. Writes lod_state only.
#include "components/bounds.h"
#include "components/camera.h"
#include "components/lod_state.h"
#include "components/plant_instance.h"
#include "components/transform.h"
#include "ecs/system.h"
#include "scenarios/scenario.h"
#include "systems/scene_assets.h"

namespace sylva {

// The six planes of a camera-relative frustum, normals pointing inside (Gribb & Hartmann 2001:
// planes from the rows of the view-projection matrix), normalised.
struct frustum_planes {
    glm::vec4 planes[6];
};
frustum_planes extract_frustum_planes(const glm::mat4& view_projection);
bool sphere_in_frustum(const frustum_planes& f, glm::vec3 center, float radius);

struct cull_system {
    static constexpr std::string_view k_name = "cull";
    static constexpr ecs::phase k_phase = ecs::phase::cull;
    using reads = ecs::reads<camera, world_transform, bounds, plant_instance, species_library,
                             shadow_settings>;
    using writes = ecs::writes<lod_state>;
    static void run(ecs::system_context<cull_system>& ctx);
};

}  // namespace sylva
