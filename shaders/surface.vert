// Every mesh Sylva draws (terrain, bark, leaves) is an instanced mesh: model vertices from the
// shared vertex buffer, one instance record (camera-relative position, yaw, scale, tint, fade,
// texture layer) per instance. SHADOW_PASS renders depth from the sun's cascade instead.
#include "common.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_instance_position_yaw;
layout(location = 4) in vec4 in_instance_scale_tint_fade_layer;

#ifdef SHADOW_PASS
uniform int u_cascade;
#endif

out vec3 v_position;  // camera-relative world position
out vec3 v_normal;
out vec2 v_uv;
out float v_tint;
flat out float v_layer;

void main() {
    float yaw = in_instance_position_yaw.w;
    float s = sin(yaw), c = cos(yaw);
    mat3 rotation = mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c);
    float scale = in_instance_scale_tint_fade_layer.x;
    vec3 world = rotation * (in_position * scale) + in_instance_position_yaw.xyz;
    v_position = world;
    v_normal = rotation * in_normal;
    v_uv = in_uv;
    v_tint = in_instance_scale_tint_fade_layer.y;
    v_layer = in_instance_scale_tint_fade_layer.w;
#ifdef SHADOW_PASS
    gl_Position = u_cascade_view_projection[u_cascade] * vec4(world, 1.0);
#else
    gl_Position = u_view_projection * vec4(world, 1.0);
#endif
}
