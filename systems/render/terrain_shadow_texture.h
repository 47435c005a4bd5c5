#pragma once
// The terrain's shadow on the GPU (resources/terrain_shadow.h): one RG32F texel per height
// sample, (height, shadow depth above it), read by shaders/shading.glsl terrain_sun_visibility
// with linear filtering, texel centres on the samples. Uploaded into the same texture whenever
// the shadow is remade (the sun moved) and only when the terrain shadows something; the frame
// loop creates no GL object for it.
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "resources/terrain_shadow.h"
#include "systems/render/gl_objects.h"

namespace sylva::render {

// The texture units shaders/shading.glsl and mesh.frag read it and the ground's normals from
// (after the shells' transfer pages, 5-9).
inline constexpr GLuint k_terrain_shadow_unit = 10;
inline constexpr GLuint k_ground_normal_unit = 11;

// Camera-relative xz to the texture coordinate of a terrain sample texture (resolution^2
// samples over size_m, origin at camera-relative `terrain_position`): (xz + m.xy) * m.z + m.w,
// sample i at (i + 0.5) / resolution.
glm::vec4 terrain_map(glm::vec3 terrain_position, std::uint32_t resolution, double size_m);

class terrain_shadow_texture {
public:
    // Brings the texture up to `shadow` (null: no terrain, or no shadows drawn); returns the
    // bytes uploaded.
    std::uint64_t update(const terrain_shadow* shadow);
    // True when the last update left a shadow worth looking up (the terrain shadows something).
    bool casts() const { return m_casts; }
    GLuint id() const { return m_texture.id(); }

    // The shadow's part of the frame uniforms' terrain parameters (shaders/common.glsl
    // u_terrain_params) for a terrain whose origin is at camera-relative `terrain_position`: x
    // plus a camera-relative y is the height above the terrain's origin, y the width of a
    // shadow's edge in metres, z 1 when the lookup is on; w (the ground normals') is left as is.
    void uniforms(glm::vec3 terrain_position, bool shadows_on, glm::vec4& params) const;

private:
    gl_texture m_texture;
    std::uint32_t m_resolution = 0;
    float m_edge_m = 0.0f;
    bool m_casts = false;
    // What the texture holds: the resource's revision and sun (two worlds drawn by one renderer
    // can share a revision number, as the sky's can).
    std::uint64_t m_revision = 0;
    glm::vec3 m_sun{0.0f};
};

}  // namespace sylva::render
