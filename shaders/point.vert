// The point representation (Deussen 2002 §5.1): each point a square splat of u_splat_px pixels
// on screen, shaded here once per sample (shading.glsl, one shadow tap) into v_color, flat
// across its pixels. SPLAT_VISIBILITY draws them as opaque splats into depth only, pushed back
// along the view ray, and SOFT_SPLATS as Gaussians of u_splat_px blended over that
// (lod/point_line_lod.h), both into the splat layer (systems/render/splat_layer.h); the
// instance's fade is then the prefix's fractional length (build_draw_list): splat j of the
// prefix is drawn at opacity clamp(fade − j, 0, 1), the last one faded
// (point_prefix::last_fade). SH_TRANSFER: the transfer of the side facing the eye
// (vertex_transfer.glsl, Behrendt 2005 §4). WRITE_ID passes the instance index on, WRITE_NORMAL
// the normal it is lit with (the line style's normal buffer; the visibility pass's too).
#if defined(WRITE_ID) || defined(SOFT_SPLATS) || defined(SPLAT_VISIBILITY)
#extension GL_ARB_shader_draw_parameters : require
#endif
#include "common.glsl"
#include "instance.glsl"

uniform float u_splat_px;  // splat side on screen, pixels
// The same on the image plane at distance one.
uniform float u_splat_plane;
// Fog-weighted sampling (point_line_lod.h fog_sample_distance): the prefix spaced a fogged
// part's samples d'·exp(ρ·r/2) apart, at most u_sample_growth_max·d', so its splats grow by the
// same factor, here from each splat's own distance. ρ = 0: no growth.
uniform float u_sample_fog;
uniform float u_sample_growth_max;
float splat_growth(vec3 world) { return min(exp(0.5 * u_sample_fog * length(world)), u_sample_growth_max); }
#ifdef WRITE_ID
flat out uint v_instance;  // index into the frame's instance records (baseInstance + instance)
#endif
#ifdef SPLAT_VISIBILITY
// ε / distance: k_soft_splat_depth_offset splat sides on the image plane at distance one, so the
// splat moves back ε = that x its distance along its view ray.
uniform float u_depth_push;
uniform int u_visibility_stride;  // lod/point_line_lod.h k_soft_splat_visibility_stride
#ifdef WRITE_NORMAL
flat out vec3 v_lit_normal;  // the line style's normal buffer (splat_visibility.frag)
#endif
#else
// A splat is one sample: shaded here once, flat across its pixels, with one shadow tap.
#define SHADOW_SINGLE_TAP
#include "shading.glsl"
layout(binding = 0) uniform sampler2DArray u_albedo;
flat out vec3 v_color;
#ifdef WRITE_NORMAL
flat out vec3 v_lit_normal;  // for the line style's normal buffer (point.frag)
#endif
#ifdef SH_TRANSFER
#include "transfer.glsl"
#include "vertex_transfer.glsl"
#endif
#ifdef SOFT_SPLATS
flat out float v_opacity;  // of this splat: 1, or less for a fractional prefix's last
#endif
#endif

void main() {
    instance_pose pose = pose_instance();
    vec3 world = pose.world;
    float layer = in_instance_scale_tint_fade_layer.w;
#ifdef WRITE_ID
    v_instance = uint(gl_BaseInstanceARB + gl_InstanceID);
#endif
#ifdef SPLAT_VISIBILITY
    float growth = splat_growth(world);
    gl_Position = u_view_projection * vec4(world * (1.0 + u_depth_push * growth), 1.0);
    gl_PointSize = u_splat_px * growth;
    // Every u_visibility_stride-th splat of the prefix only. A fractional prefix's last splat
    // (instance fade < its index + 1) hides nothing until it is whole: it fades in over what is
    // behind it.
    int rank = gl_VertexID - gl_BaseVertexARB;
    if (rank % u_visibility_stride != 0 || in_instance_scale_tint_fade_layer.z < float(rank) + 1.0)
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume
#ifdef WRITE_NORMAL
    // The normal the blend pass lights the splat with: Luft 2007's realigned one as it is (it
    // points out of the crown), any other turned to face the eye, as below.
    vec3 lit = normalize(pose.rotation * in_normal);
#ifndef IMPLICIT_LIGHTING
    if (dot(lit, world) > 0.0) lit = -lit;
#endif
    v_lit_normal = lit;
#endif
#else
    gl_Position = u_view_projection * vec4(world, 1.0);
    gl_PointSize = u_splat_px * splat_growth(world);
#ifdef SOFT_SPLATS
    v_opacity = clamp(in_instance_scale_tint_fade_layer.z - float(gl_VertexID - gl_BaseVertexARB), 0.0, 1.0);
#endif
    // As line.frag shades samples: the texture's colour where the point was baked (a slightly
    // filtered level), the surface's side that faces the eye, lit as foliage when the material
    // is a leaf.
    vec3 normal = pose.rotation * in_normal;
#ifdef IMPLICIT_LIGHTING
    normal *= population_ambient(in_position);  // the normal's length is k_a (Luft 2007 §3.2)
#endif
    vec4 albedo = textureLod(u_albedo, vec3(in_uv, layer), 1.0);
    vec3 base = albedo.rgb * (1.0 + 0.18 * in_instance_scale_tint_fade_layer.y);
#if defined(SH_TRANSFER)
#ifdef IMPLICIT_LIGHTING
    sh_ambient = min(length(normal), 1.0);
#endif
    vec4 sphere = plant_sphere(in_instance_position_yaw.xyz, pose.scale, layer);
    float sh_exit = sphere_exit_distance(world, sphere);
    float front[9], back[9];
    turned_transfer(pose.c, pose.s, front, back);
    float sun_front = sh_transfer_sun(front), sun_back = sh_transfer_sun(back);
    // The side seen is the one whose normal faces the eye (the eye is at the origin).
    bool front_seen = dot(normal, world) <= 0.0;
    vec3 sh_sky = front_seen ? sh_transfer_sky(front) : sh_transfer_sky(back);
    vec2 sh_sun = front_seen ? vec2(sun_front, sun_back) : vec2(sun_back, sun_front);
#ifdef WRITE_NORMAL
    v_lit_normal = normalize(front_seen ? normal : -normal);
#endif
#if defined(MATERIAL_LEAF)
    v_color = shade_transfer(base, sh_sky, sh_sun.x, sh_sun.y, world, sh_exit, true);
#else
    v_color = shade_transfer(base, sh_sky, sh_sun.x, sh_sun.y, world, sh_exit, false);
#endif
#elif defined(IMPLICIT_LIGHTING) && defined(MATERIAL_LEAF)
    v_color = shade_implicit(base, normal, world, true);
#ifdef WRITE_NORMAL
    v_lit_normal = normalize(normal);
#endif
#elif defined(IMPLICIT_LIGHTING)
    v_color = shade_implicit(base, normal, world, false);
#ifdef WRITE_NORMAL
    v_lit_normal = normalize(normal);
#endif
#else
    vec3 n = normalize(normal);
    if (dot(n, world) > 0.0) n = -n;
#ifdef WRITE_NORMAL
    v_lit_normal = n;
#endif
#if defined(MATERIAL_LEAF)
    v_color = shade_surface(base, n, world, true);
#else
    v_color = shade_surface(base, n, world, false);
#endif
#endif
#endif
}
