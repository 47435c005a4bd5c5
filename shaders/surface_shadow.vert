// Shadow casters (Deussen 2002 §6.4, cascaded shadow maps): the instance's vertex
// (instance.glsl) into the sun's cascade u_cascade, with the texture coordinates the
// alpha-tested casters' fragment shader reads (surface_shadow.frag). PRIMITIVE_POINTS: each
// point a splat as wide as the casters are spaced (lod/point_line_lod.h
// k_shadow_sample_texels), pushed away from the sun. Lines are GL's own, one texel wide.
#include "common.glsl"
#include "instance.glsl"

uniform int u_cascade;
#ifdef PRIMITIVE_POINTS
// The casters' spacing on the image plane at distance one (k_shadow_sample_spacing·d'), which
// is also their width (c_p = 1).
uniform float u_splat_plane;
uniform float u_splat_texels;  // smallest shadow splat, texels (k_shadow_sample_texels)
uniform float u_shadow_push;   // widths each moves away from the sun (k_shadow_splat_push)
#endif

out vec2 v_uv;
flat out float v_layer;

void main() {
    instance_pose pose = pose_instance();
    vec3 world = pose.world;
    v_uv = in_uv;
    v_layer = in_instance_scale_tint_fade_layer.w;
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
}
