// Every mesh Sylva draws (terrain, bark, leaves, billboards) is an instanced mesh: model vertices from the
// shared vertex buffer, one instance record (camera-relative position, yaw, scale, tint, fade,
// texture layer) per instance. SHADOW_PASS renders depth from the sun's cascade instead.
// WRITE_ID (measurement) passes the draw-list instance index on for the ID buffer.
// PRIMITIVE_POINTS draws the point representation (Deussen 2002 §5.1): each point a square
// splat of u_splat_px pixels on screen; in a shadow cascade a splat as wide as the casters are
// spaced (lod/point_line_lod.h k_shadow_sample_texels), pushed away from the sun.
// SPLAT_VISIBILITY draws them as opaque splats into depth only, pushed back along the view ray,
// and SOFT_SPLATS as Gaussians of u_splat_px blended over that (lod/point_line_lod.h), both
// into the splat layer (systems/render/splat_layer.h); the
// instance's fade is then the prefix's fractional length (build_draw_list): splat j of the
// prefix is drawn at opacity clamp(fade − j, 0, 1), the last one faded (point_prefix::last_fade).
// PRIMITIVE_LINES hands lines to line.geom, which widens them to d' pixels.
// SH_TRANSFER lights by the precomputed radiance transfer streamed with the vertices
// (transfer.glsl, Behrendt 2005 §4): here the transfer is turned by the instance's yaw and
// dotted with the sky's and the sun's SH; the sun's visibility is looked up per fragment (per
// point for splats).
#if defined(WRITE_ID) || defined(SOFT_SPLATS) || defined(SPLAT_VISIBILITY)
#extension GL_ARB_shader_draw_parameters : require
#endif
#include "common.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_instance_position_yaw;
layout(location = 4) in vec4 in_instance_scale_tint_fade_layer;
#if defined(SH_TRANSFER) && !defined(SHADOW_PASS)
#include "transfer.glsl"
// models/mesh.h vertex_transfer: 9 halves for the side the normal faces, 9 for the other.
layout(location = 5) in vec4 in_transfer0;
layout(location = 6) in vec4 in_transfer1;
layout(location = 7) in vec4 in_transfer2;
layout(location = 8) in vec4 in_transfer3;
layout(location = 9) in vec4 in_transfer4;
#if defined(MATERIAL_BILLBOARD_CLOUD) || defined(MATERIAL_BILLBOARD)
// Billboard quads reach across the plant: the sun's exit from its sphere is found per fragment.
flat out vec4 v_sh_sphere;
#else
// Samples (points, lines): the side facing the eye is the one seen, so x/rgb are that side's,
// y the other's. Triangles: the side the normal faces, and v_sh_sky_back the other side's
// (surface.frag picks by gl_FrontFacing).
out vec3 v_sh_sky;    // T . L_sky
out vec2 v_sh_sun;    // T . Y(sun) of the two sides
out float v_sh_exit;  // metres the sun's ray runs inside the plant's own sphere
#if !defined(PRIMITIVE_POINTS) && !defined(PRIMITIVE_LINES)
out vec3 v_sh_sky_back;
#endif
#endif
#endif

#ifdef SHADOW_PASS
uniform int u_cascade;
#endif
#if defined(PRIMITIVE_POINTS) && !defined(SHADOW_PASS) && !defined(SPLAT_VISIBILITY)
// A splat is one sample: shaded here once (shading.glsl), flat across its pixels, with one
// shadow tap.
#define SHADOW_SINGLE_TAP
#include "shading.glsl"
layout(binding = 0) uniform sampler2DArray u_albedo;
flat out vec3 v_color;
#endif
#ifdef SOFT_SPLATS
flat out float v_opacity;  // of this splat: 1, or less for a fractional prefix's last
#endif
#ifdef PRIMITIVE_POINTS
uniform float u_splat_px;     // splat side on screen, pixels
// The same on the image plane at distance one; in a shadow cascade, the casters' spacing there
// (k_shadow_sample_spacing·d'), which is also their width (c_p = 1).
uniform float u_splat_plane;
#ifdef SHADOW_PASS
uniform float u_splat_texels;  // smallest shadow splat, texels (k_shadow_sample_texels)
uniform float u_shadow_push;   // widths each moves away from the sun (k_shadow_splat_push)
#else
// Fog-weighted sampling (point_line_lod.h fog_sample_distance): the prefix spaced a fogged
// part's samples d'·exp(ρ·r/2) apart, at most u_sample_growth_max·d', so its splats grow by the
// same factor, here from each splat's own distance. ρ = 0: no growth.
uniform float u_sample_fog;
uniform float u_sample_growth_max;
float splat_growth(vec3 world) { return min(exp(0.5 * u_sample_fog * length(world)), u_sample_growth_max); }
#endif
#endif
#ifdef SPLAT_VISIBILITY
// ε / distance: k_soft_splat_depth_offset splat sides on the image plane at distance one, so the
// splat moves back ε = that x its distance along its view ray.
uniform float u_depth_push;
uniform int u_visibility_stride;  // lod/point_line_lod.h k_soft_splat_visibility_stride
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
#if defined(SH_TRANSFER) && !defined(SHADOW_PASS)
    vec4 sphere = plant_sphere(in_instance_position_yaw.xyz, scale, v_layer);
#if defined(MATERIAL_BILLBOARD_CLOUD) || defined(MATERIAL_BILLBOARD)
    v_sh_sphere = sphere;
#else
    v_sh_exit = sphere_exit_distance(world, sphere);
    float front[9] = float[9](in_transfer0.x, in_transfer0.y, in_transfer0.z, in_transfer0.w, in_transfer1.x,
                              in_transfer1.y, in_transfer1.z, in_transfer1.w, in_transfer2.x);
    float back[9] = float[9](in_transfer2.y, in_transfer2.z, in_transfer2.w, in_transfer3.x, in_transfer3.y,
                             in_transfer3.z, in_transfer3.w, in_transfer4.x, in_transfer4.y);
    sh_rotate_about_y(front, c, s);
    sh_rotate_about_y(back, c, s);
    float sun_front = sh_transfer_sun(front), sun_back = sh_transfer_sun(back);
#if defined(PRIMITIVE_POINTS) || defined(PRIMITIVE_LINES)
    // The side seen is the one whose normal faces the eye (the eye is at the origin).
    bool front_seen = dot(v_normal, world) <= 0.0;
    v_sh_sky = front_seen ? sh_transfer_sky(front) : sh_transfer_sky(back);
    v_sh_sun = front_seen ? vec2(sun_front, sun_back) : vec2(sun_back, sun_front);
#else
    v_sh_sky = sh_transfer_sky(front);
    v_sh_sky_back = sh_transfer_sky(back);
    v_sh_sun = vec2(sun_front, sun_back);
#endif
#endif
#endif
#if defined(SPLAT_VISIBILITY)
    float growth = splat_growth(world);
    gl_Position = u_view_projection * vec4(world * (1.0 + u_depth_push * growth), 1.0);
    gl_PointSize = u_splat_px * growth;
    // Every u_visibility_stride-th splat of the prefix only. A fractional prefix's last splat
    // (instance fade < its index + 1) hides nothing until it is whole: it fades in over what is
    // behind it.
    int rank = gl_VertexID - gl_BaseVertexARB;
    if (rank % u_visibility_stride != 0 || in_instance_scale_tint_fade_layer.z < float(rank) + 1.0)
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume
#elif defined(SHADOW_PASS)
#ifdef PRIMITIVE_POINTS
    // Away from the sun along its ray by u_shadow_push of its own widths: the splat then shades
    // what lies behind the leaves it stands for, not the leaves beside it (point_line_lod.h
    // k_shadow_splat_push). Where its shadow falls is unchanged.
    gl_PointSize = max(u_splat_texels, u_splat_plane * length(world) / u_cascade_texel_world[u_cascade]);
    vec3 pushed = world - u_sun_direction.xyz * (u_shadow_push * gl_PointSize * u_cascade_texel_world[u_cascade]);
    gl_Position = u_cascade_view_projection[u_cascade] * vec4(pushed, 1.0);
#else
    gl_Position = u_cascade_view_projection[u_cascade] * vec4(world, 1.0);
#endif
#else
    gl_Position = u_view_projection * vec4(world, 1.0);
#ifdef PRIMITIVE_POINTS
    gl_PointSize = u_splat_px * splat_growth(world);
#ifdef SOFT_SPLATS
    v_opacity = clamp(in_instance_scale_tint_fade_layer.z - float(gl_VertexID - gl_BaseVertexARB), 0.0, 1.0);
#endif
    // As surface.frag shades samples: the texture's colour where the point was baked (a
    // slightly filtered level), the surface's side that faces the eye, lit as foliage when the
    // material is a leaf.
    vec4 albedo = textureLod(u_albedo, vec3(v_uv, v_layer), 1.0);
    vec3 base = albedo.rgb * (1.0 + 0.18 * v_tint);
#if defined(SH_TRANSFER)
#if defined(MATERIAL_LEAF)
    v_color = shade_transfer(base, v_sh_sky, v_sh_sun.x, v_sh_sun.y, world, v_sh_exit, true);
#else
    v_color = shade_transfer(base, v_sh_sky, v_sh_sun.x, v_sh_sun.y, world, v_sh_exit, false);
#endif
#else
    vec3 n = normalize(v_normal);
    if (dot(n, world) > 0.0) n = -n;
#if defined(MATERIAL_LEAF) || defined(MATERIAL_BILLBOARD)
    v_color = shade_surface(base, n, world, true);
#else
    v_color = shade_surface(base, n, world, false);
#endif
#endif
#endif
#endif
}
