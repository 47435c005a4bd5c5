// Meshes, billboard clouds and lines in the view: the instance's vertex (instance.glsl) to the
// camera, with what mesh.frag, cloud.frag and line.frag shade by. WRITE_ID (measurement) passes
// the draw-list instance index on for the ID buffer. PRIMITIVE_LINES with LINE_QUADS hands lines
// to line.geom, which widens them to d' pixels.
// SH_TRANSFER lights by the precomputed radiance transfer streamed with the vertices
// (vertex_transfer.glsl, Behrendt 2005 §4): here the transfer is turned by the instance's yaw
// and dotted with the sky's and the sun's SH; the sun's visibility is looked up per fragment.
// Shadow casters: surface_shadow.vert; point splats: point.vert.
#ifdef WRITE_ID
#extension GL_ARB_shader_draw_parameters : require
#endif
#include "common.glsl"
#include "instance.glsl"
#ifdef SH_TRANSFER
#include "transfer.glsl"
#include "vertex_transfer.glsl"
#if defined(MATERIAL_BILLBOARD_CLOUD) || defined(MATERIAL_BILLBOARD)
// Billboard quads reach across the plant: the sun's exit from its sphere is found per fragment.
flat out vec4 v_sh_sphere;
#else
// Lines: the side facing the eye is the one seen, so x/rgb are that side's, y the other's.
// Triangles: the side the normal faces, and v_sh_sky_back the other side's (mesh.frag picks
// by gl_FrontFacing).
out vec3 v_sh_sky;    // T . L_sky
out vec2 v_sh_sun;    // T . Y(sun) of the two sides
out float v_sh_exit;  // metres the sun's ray runs inside the plant's own sphere
#if !defined(PRIMITIVE_LINES)
out vec3 v_sh_sky_back;
#endif
#endif
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
#if defined(IMPLICIT_LIGHTING) && (defined(MATERIAL_BILLBOARD) || defined(MATERIAL_BILLBOARD_CLOUD))
out float v_population;  // population_ambient: the page's k_a is read per fragment
#endif

void main() {
    instance_pose pose = pose_instance();
    vec3 world = pose.world;
    v_position = world;
    v_normal = pose.rotation * pose.model_normal;
#if defined(IMPLICIT_LIGHTING) && (defined(MATERIAL_BILLBOARD) || defined(MATERIAL_BILLBOARD_CLOUD))
    v_population = population_ambient(in_position);
#elif defined(IMPLICIT_LIGHTING)
    v_normal *= population_ambient(in_position);  // the normal's length is k_a (Luft 2007 §3.2)
#endif
    v_uv = pose.uv;
    v_tint = in_instance_scale_tint_fade_layer.y;
    v_layer = in_instance_scale_tint_fade_layer.w;
#if defined(MATERIAL_BILLBOARD) || defined(MATERIAL_BILLBOARD_CLOUD)
    v_yaw_cos_sin = vec2(pose.c, pose.s);
#endif
#if defined(FADE_DISSOLVE) || defined(MATERIAL_BILLBOARD_CLOUD)
    v_fade = in_instance_scale_tint_fade_layer.z;
#endif
#ifdef WRITE_ID
    v_instance = uint(gl_BaseInstanceARB + gl_InstanceID);
#endif
#ifdef SH_TRANSFER
    vec4 sphere = plant_sphere(in_instance_position_yaw.xyz, pose.scale, v_layer);
#if defined(MATERIAL_BILLBOARD_CLOUD) || defined(MATERIAL_BILLBOARD)
    v_sh_sphere = sphere;
#else
    v_sh_exit = sphere_exit_distance(world, sphere);
    float front[9], back[9];
    turned_transfer(pose.c, pose.s, front, back);
    float sun_front = sh_transfer_sun(front), sun_back = sh_transfer_sun(back);
#if defined(PRIMITIVE_LINES)
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
    gl_Position = u_view_projection * vec4(world, 1.0);
}
