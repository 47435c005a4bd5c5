#include "systems/cull_system.h"

#include <glm/geometric.hpp>

#include "ecs/parallel.h"

namespace sylva {

frustum_planes extract_frustum_planes(const glm::mat4& m) {
    frustum_planes f;
    const glm::vec4 row0{m[0][0], m[1][0], m[2][0], m[3][0]};
    const glm::vec4 row1{m[0][1], m[1][1], m[2][1], m[3][1]};
    const glm::vec4 row2{m[0][2], m[1][2], m[2][2], m[3][2]};
    const glm::vec4 row3{m[0][3], m[1][3], m[2][3], m[3][3]};
    f.planes[0] = row3 + row0;  // left
    f.planes[1] = row3 - row0;  // right
    f.planes[2] = row3 + row1;  // bottom
    f.planes[3] = row3 - row1;  // top
    f.planes[4] = row3 + row2;  // near
    f.planes[5] = row3 - row2;  // far
    for (auto& p : f.planes) p /= glm::length(glm::vec3(p));
    return f;
}

bool sphere_in_frustum(const frustum_planes& f, glm::vec3 center, float radius) {
    for (const auto& p : f.planes)
        if (glm::dot(glm::vec3(p), center) + p.w < -radius) return false;
    return true;
}

void cull_system::run(ecs::system_context<cull_system>& ctx) {
    const camera& cam = ctx.single<camera>();
    const frustum_planes frustum = extract_frustum_planes(cam.projection * cam.view);
    const auto& library = ctx.resource<species_library>().species;
    const float shadow_distance = ctx.resource<shadow_settings>().max_distance_m;
    auto plants = ctx.query<const world_transform, const bounds, const plant_instance, lod_state>();
    ctx.parallel_for(plants.size(), ecs::k_default_chunk, [&](std::size_t begin, std::size_t end, std::size_t) {
        plants.each_chunk(begin, end, [&](ecs::entity, const world_transform& t, const bounds& b,
                                          const plant_instance& p, lod_state& lod) {
            // Camera-relative in double, then float: exact to millimetres anywhere on Earth.
            const glm::vec3 base{t.position - cam.position};
            const glm::vec3 center = base + glm::vec3(0.0f, b.center_height, 0.0f);
            const float distance = glm::length(center) - b.radius;
            const auto& species = library[static_cast<std::size_t>(p.species)];
            const float max_distance = species.max_distance_m * t.scale * cam.lod_scale;
            const bool near_enough = distance < max_distance;
            lod.visible = near_enough && sphere_in_frustum(frustum, center, b.radius) ? 1 : 0;
            lod.in_shadow_range = near_enough && distance < shadow_distance ? 1 : 0;
        });
    });
}

}  // namespace sylva
