// The line representation's samples in the view (Deussen 2002 §5.2) of bark and leaf
// (MATERIAL_LEAF) parts: each fragment takes the texture's colour where the line was baked (a
// slightly filtered level: a line stands for more surface than one texel), is never
// alpha-tested (the bake put it on an opaque texel), and is lit with its surface's normal
// turned towards the eye, as a leaf card's visible side is; by SH_TRANSFER from the transfer
// surface.vert turned to the side seen.
#include "common.glsl"
#include "shading.glsl"
#ifdef LINE_QUADS
// Wide lines reach this shader through line.geom, whose outputs are g_*: the same varyings.
#define v_position g_position
#define v_normal g_normal
#define v_uv g_uv
#define v_tint g_tint
#define v_layer g_layer
#define v_instance g_instance
#define v_sh_sky g_sh_sky
#define v_sh_sun g_sh_sun
#define v_sh_exit g_sh_exit
#endif
#include "surface_inputs.glsl"
#ifdef SH_TRANSFER
#include "transfer.glsl"
// The side facing the eye first (surface.vert).
in vec3 v_sh_sky;
in vec2 v_sh_sun;
in float v_sh_exit;
#endif

void main() {
    vec4 albedo = textureLod(u_albedo, vec3(v_uv, v_layer), 1.0);
    vec3 base = albedo.rgb * (1.0 + 0.18 * v_tint);
    vec3 n = normalize(v_normal);
    if (dot(n, v_position) > 0.0) n = -n;  // the side of the surface that faces the eye
#if defined(SH_TRANSFER) && defined(IMPLICIT_LIGHTING)
    sh_ambient = min(length(v_normal), 1.0);
#endif
#if defined(SH_TRANSFER) && defined(MATERIAL_LEAF)
    out_color = vec4(shade_transfer(base, v_sh_sky, v_sh_sun.x, v_sh_sun.y, v_position, v_sh_exit, true), 1.0);
#elif defined(SH_TRANSFER)
    out_color = vec4(shade_transfer(base, v_sh_sky, v_sh_sun.x, v_sh_sun.y, v_position, v_sh_exit, false), 1.0);
#elif defined(IMPLICIT_LIGHTING) && defined(MATERIAL_LEAF)
    out_color = vec4(shade_implicit(base, v_normal, v_position, true), 1.0);
#elif defined(IMPLICIT_LIGHTING)
    out_color = vec4(shade_implicit(base, v_normal, v_position, false), 1.0);
#elif defined(MATERIAL_LEAF)
    out_color = vec4(shade_surface(base, n, v_position, true), 1.0);
#else
    out_color = vec4(shade_surface(base, n, v_position, false), 1.0);
#endif
#ifdef WRITE_NORMAL
#ifdef IMPLICIT_LIGHTING
    out_normal = vec4(normalize(v_normal) * 0.5 + 0.5, 1.0);
#else
    out_normal = vec4(n * 0.5 + 0.5, 1.0);
#endif
#endif
#ifdef WRITE_ID
    out_id = v_instance + 1u;
#endif
}
