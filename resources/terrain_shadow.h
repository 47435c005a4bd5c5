#pragma once
// The terrain's shadow under the current sun (lighting/terrain_shadow.h): the terrain's heights,
// set at spawn, and per height sample the depth of the shadow above the ground, remade by
// update_terrain_shadow whenever the sun moves; the renderer uploads it as a texture
// (systems/render/terrain_shadow_texture.h) that every surface's sun term looks up
// (shaders/shading.glsl terrain_sun_visibility). The terrain itself casts nothing into the
// shadow cascades.
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace sylva {

struct terrain_shadow {
    // The terrain (models/terrain/terrain.h heightfield): resolution^2 heights, row-major (z
    // rows, x columns), relative to the terrain's origin, spanning [-size/2, size/2] in x and z.
    std::uint32_t resolution = 0;
    double size_m = 0.0;
    std::vector<float> heights;

    // Written by update_terrain_shadow: per sample (height h, shadow depth H - h) interleaved,
    // what the texture holds; the sun direction it was made for; the deepest shadow (0: the
    // terrain shadows nothing under this sun and the renderer skips the lookup); a revision
    // counted up each time the texels change.
    std::vector<float> texels;
    std::vector<float> shadow_heights;  // H, the sweep's scratch, reused
    glm::vec3 sun_direction{0.0f};
    float deepest_m = 0.0f;
    std::uint64_t revision = 0;

    double spacing() const { return resolution > 1 ? size_m / double(resolution - 1) : 0.0; }
};

}  // namespace sylva
