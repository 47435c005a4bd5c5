#pragma once
// The per-frame uniform block, std140, mirrored by `frame_block` in shaders/common.glsl.
// Every field is a vec4 or mat4 so std140 adds no hidden padding; offsets are asserted below.
#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace sylva::render {

struct frame_uniforms {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 view_projection{1.0f};
    glm::mat4 inverse_view_projection{1.0f};
    glm::mat4 cascade_view_projection[4]{};
    glm::vec4 cascade_split_far{0.0f};
    glm::vec4 sun_direction{0.0f};  // w: shadows on
    glm::vec4 sun_radiance{0.0f};   // w: cascade count
    glm::vec4 sh_irradiance[9]{};
    glm::vec4 fog{0.0f};
    glm::vec4 params{0.0f};  // x exposure, y shadow texel uv, z time, w ground uv scale
    glm::vec4 cascade_texel_world{0.0f};
    glm::vec4 sh_radiance[9]{};  // the sky's radiance SH, rgb (precomputed radiance transfer)
    glm::vec4 sun_sh[3]{};       // SH basis at the sun's direction, 9 values packed 4 + 4 + 1
    // Camera-relative xz to the terrain's sample textures (ground normals, terrain shadow):
    // (xz offset, scale, half texel); then the lookups' parameters (height offset, shadow edge
    // width m, shadow on, ground normals on) (systems/render/terrain_shadow_texture.h).
    glm::vec4 terrain_map{0.0f};
    glm::vec4 terrain_params{0.0f};
};
static_assert(offsetof(frame_uniforms, cascade_view_projection) == 256);
static_assert(offsetof(frame_uniforms, cascade_split_far) == 512);
static_assert(offsetof(frame_uniforms, sh_irradiance) == 560);
static_assert(offsetof(frame_uniforms, fog) == 704);
static_assert(offsetof(frame_uniforms, cascade_texel_world) == 736);
static_assert(offsetof(frame_uniforms, sh_radiance) == 752);
static_assert(offsetof(frame_uniforms, sun_sh) == 896);
static_assert(offsetof(frame_uniforms, terrain_map) == 944);
static_assert(sizeof(frame_uniforms) == 976);

}  // namespace sylva::render
