// Deussen 2002 §5.2 draws a part's lines with width d' (Eq. 2 counts their image area as
// length times d'). Core-profile GL only guarantees lines one pixel wide, so each line becomes a
// screen-aligned quad of u_line_width_px pixels here. Varyings pass through unchanged (flat
// ones from the first vertex, which is the provoking vertex of GL_LINES by default).
#ifdef WRITE_ID
#extension GL_ARB_shader_draw_parameters : require
#endif
#include "common.glsl"

layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

uniform float u_line_width_px;
uniform vec2 u_viewport_px;

in vec3 v_position[];
in vec3 v_normal[];
in vec2 v_uv[];
in float v_tint[];
flat in float v_layer[];
#ifdef WRITE_ID
flat in uint v_instance[];
#endif
#ifdef SH_TRANSFER
in vec3 v_sh_sky[];
in vec2 v_sh_sun[];
in float v_sh_exit[];
out vec3 g_sh_sky;
out vec2 g_sh_sun;
out float g_sh_exit;
#endif

out vec3 g_position;
out vec3 g_normal;
out vec2 g_uv;
out float g_tint;
flat out float g_layer;
#ifdef WRITE_ID
flat out uint g_instance;
#endif

void emit(int i, vec2 offset_ndc) {
    vec4 p = gl_in[i].gl_Position;
    gl_Position = vec4(p.xy + offset_ndc * p.w, p.zw);
    g_position = v_position[i];
    g_normal = v_normal[i];
    g_uv = v_uv[i];
    g_tint = v_tint[i];
    g_layer = v_layer[0];
#ifdef SH_TRANSFER
    g_sh_sky = v_sh_sky[i];
    g_sh_sun = v_sh_sun[i];
    g_sh_exit = v_sh_exit[i];
#endif
#ifdef WRITE_ID
    g_instance = v_instance[0];
#endif
    EmitVertex();
}

void main() {
    vec4 a = gl_in[0].gl_Position;
    vec4 b = gl_in[1].gl_Position;
    // Lines crossing the eye plane are dropped rather than clipped: a grass blade or twig that
    // close is drawn as triangles by Eq. 2 anyway.
    if (a.w <= 0.0 || b.w <= 0.0) return;
    vec2 a_px = a.xy / a.w * 0.5 * u_viewport_px;
    vec2 b_px = b.xy / b.w * 0.5 * u_viewport_px;
    vec2 dir = b_px - a_px;
    float len = length(dir);
    dir = len > 1e-6 ? dir / len : vec2(1.0, 0.0);
    vec2 side = vec2(-dir.y, dir.x) * (0.5 * u_line_width_px);
    vec2 side_ndc = side / (0.5 * u_viewport_px);
    emit(0, side_ndc);
    emit(0, -side_ndc);
    emit(1, side_ndc);
    emit(1, -side_ndc);
    EndPrimitive();
}
