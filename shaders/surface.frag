// Shading of terrain, bark, leaves and baked billboards: sun light with cascaded shadows plus sky
// light from the environment's SH irradiance, leaves lit from behind by transmitted sunlight;
// then fog and tone mapping. MATERIAL_LEAF and MATERIAL_BILLBOARD alpha-test (also in the shadow
// pass, so they cast leaf-shaped shadows); billboards take their normal from a normal map baked
// from the plant (models/crossed_billboard.h) and are shaded like leaves with it.
// WRITE_ID also writes which instance covers the pixel (measure/: coverage, lighting jumps).
// PRIMITIVE_POINTS / PRIMITIVE_LINES shade the point and line representation (Deussen 2002):
// each sample takes the texture's colour where it was baked (a slightly filtered level: a
// splat stands for more surface than one texel), is never alpha-tested (the bake put it on an
// opaque texel), and is lit with its surface's normal turned towards the eye, as a leaf card's
// visible side is.
#include "common.glsl"

#ifdef LINE_QUADS
// Wide lines reach this shader through line.geom, whose outputs are g_*: the same varyings.
#define v_position g_position
#define v_normal g_normal
#define v_uv g_uv
#define v_tint g_tint
#define v_layer g_layer
#define v_instance g_instance
#endif

in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in float v_tint;
flat in float v_layer;
#ifdef MATERIAL_BILLBOARD
flat in vec2 v_yaw_cos_sin;
layout(binding = 2) uniform sampler2DArray u_normal_map;  // model-space normals * 0.5 + 0.5
#endif
#ifdef WRITE_ID
flat in uint v_instance;
layout(location = 1) out uint out_id;  // ID buffer: instance index + 1 (0 = nothing drawn)
#endif

layout(binding = 0) uniform sampler2DArray u_albedo;
#ifndef SHADOW_PASS
#include "shading.glsl"
layout(location = 0) out vec4 out_color;
#endif
#if defined(PRIMITIVE_POINTS) && !defined(SHADOW_PASS)
flat in vec3 v_color;  // shaded per point in surface.vert
#endif

#if defined(PRIMITIVE_POINTS) || defined(PRIMITIVE_LINES)
#define PRIMITIVE_SAMPLES
#endif

void main() {
#if defined(PRIMITIVE_POINTS) && !defined(SHADOW_PASS)
    out_color = vec4(v_color, 1.0);
#ifdef WRITE_ID
    out_id = v_instance + 1u;
#endif
    return;
#endif
#if defined(MATERIAL_GROUND)
    vec4 albedo = texture(u_albedo, vec3(v_uv * u_params.w, v_layer));
#elif defined(PRIMITIVE_SAMPLES)
    vec4 albedo = textureLod(u_albedo, vec3(v_uv, v_layer), 1.0);
#else
    vec4 albedo = texture(u_albedo, vec3(v_uv, v_layer));
#endif
#if (defined(MATERIAL_LEAF) || defined(MATERIAL_BILLBOARD)) && !defined(PRIMITIVE_SAMPLES)
    if (albedo.a < 0.5) discard;
#endif
#ifndef SHADOW_PASS
    vec3 base = albedo.rgb * (1.0 + 0.18 * v_tint);
    vec3 n = normalize(v_normal);
#if defined(PRIMITIVE_SAMPLES)
    if (dot(n, v_position) > 0.0) n = -n;  // the side of the surface that faces the eye
#elif defined(MATERIAL_LEAF)
    if (!gl_FrontFacing) n = -n;  // leaves are thin double-sided cards
#endif
#ifdef MATERIAL_BILLBOARD
    // The baked normal faces the side the billboard was rendered from; seen from the other
    // side (which shows the mirror image), reflect it through the quad's plane.
    vec3 plane = n;
    vec3 m = texture(u_normal_map, vec3(v_uv, v_layer)).xyz * 2.0 - 1.0;
    float c = v_yaw_cos_sin.x, s = v_yaw_cos_sin.y;
    n = normalize(mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c) * m);
    if (dot(plane, -v_position) < 0.0) n -= 2.0 * dot(n, plane) * plane;
#endif
#if defined(MATERIAL_LEAF) || defined(MATERIAL_BILLBOARD)
    out_color = vec4(shade_surface(base, n, v_position, true), 1.0);
#else
    out_color = vec4(shade_surface(base, n, v_position, false), 1.0);
#endif
#ifdef WRITE_ID
    out_id = v_instance + 1u;
#endif
#endif
}
