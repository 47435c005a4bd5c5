// Every mesh Sylva draws (terrain, bark, leaves, billboards) is an instanced mesh: model vertices from the
// shared vertex buffer, one instance record (camera-relative position, yaw, scale, tint, fade,
// texture layer) per instance. SHADOW_PASS renders depth from the sun's cascade instead.
// WRITE_ID (measurement) passes the draw-list instance index on for the ID buffer.
// PRIMITIVE_POINTS draws the point representation (Deussen 2002 §5.1): each point a square
// splat of u_splat_px pixels on screen; in a shadow cascade the same world footprint (the
// splat's image-plane size times the distance from the eye) in shadow-map texels.
// PRIMITIVE_LINES hands lines to line.geom, which widens them to d' pixels.
#ifdef WRITE_ID
#extension GL_ARB_shader_draw_parameters : require
#endif
#include "common.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_instance_position_yaw;
layout(location = 4) in vec4 in_instance_scale_tint_fade_layer;

#ifdef SHADOW_PASS
uniform int u_cascade;
#endif
#if defined(PRIMITIVE_POINTS) && !defined(SHADOW_PASS)
// A splat is one sample: shaded here once (shading.glsl), flat across its pixels.
#include "shading.glsl"
layout(binding = 0) uniform sampler2DArray u_albedo;
flat out vec3 v_color;
#endif
#ifdef PRIMITIVE_POINTS
uniform float u_splat_px;     // splat side on screen, pixels
uniform float u_splat_plane;  // the same on the image plane at distance one
uniform float u_splat_texels; // smallest splat in a shadow map, texels (√c_p: c_p texels' area)
#endif

out vec3 v_position;  // camera-relative world position
out vec3 v_normal;
out vec2 v_uv;
out float v_tint;
flat out float v_layer;
#ifdef WRITE_ID
flat out uint v_instance;  // index into the frame's instance records (baseInstance + instance)
#endif
#if defined(MATERIAL_BILLBOARD) || defined(MATERIAL_BILLBOARD_CLOUD)
flat out vec2 v_yaw_cos_sin;  // rotates the normal map's model-space normals into the world
#endif
#if defined(FADE_DISSOLVE) || defined(MATERIAL_BILLBOARD_CLOUD)
flat out float v_fade;  // instance_gpu::fade: how much of this representation is drawn
#endif

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
#if defined(MATERIAL_BILLBOARD) || defined(MATERIAL_BILLBOARD_CLOUD)
    v_yaw_cos_sin = vec2(c, s);
#endif
#if defined(FADE_DISSOLVE) || defined(MATERIAL_BILLBOARD_CLOUD)
    v_fade = in_instance_scale_tint_fade_layer.z;
#endif
#ifdef WRITE_ID
    v_instance = uint(gl_BaseInstanceARB + gl_InstanceID);
#endif
#ifdef SHADOW_PASS
    gl_Position = u_cascade_view_projection[u_cascade] * vec4(world, 1.0);
#ifdef PRIMITIVE_POINTS
    gl_PointSize = max(u_splat_texels, u_splat_plane * length(world) / u_cascade_texel_world[u_cascade]);
#endif
#else
    gl_Position = u_view_projection * vec4(world, 1.0);
#ifdef PRIMITIVE_POINTS
    gl_PointSize = u_splat_px;
    // As surface.frag shades samples: the texture's colour where the point was baked (a
    // slightly filtered level), the surface's side that faces the eye, lit as foliage when the
    // material is a leaf.
    vec4 albedo = textureLod(u_albedo, vec3(v_uv, v_layer), 1.0);
    vec3 base = albedo.rgb * (1.0 + 0.18 * v_tint);
    vec3 n = normalize(v_normal);
    if (dot(n, world) > 0.0) n = -n;
#if defined(MATERIAL_LEAF) || defined(MATERIAL_BILLBOARD)
    v_color = shade_surface(base, n, world, true);
#else
    v_color = shade_surface(base, n, world, false);
#endif
#endif
#endif
}
