// The point representation's splats (Deussen 2002 §5.1), shaded once per point in
// surface.vert (v_color): opaque squares in the view, or with SOFT_SPLATS the Gaussians of
// soft splats (lod/point_line_lod.h soft_splat_peak_alpha) of peak opacity u_soft_alpha,
// blended into the splat layer (systems/render/splat_layer.h) with their nearest depth.
flat in vec3 v_color;
layout(location = 0) out vec4 out_color;
#ifdef WRITE_NORMAL
flat in vec3 v_lit_normal;  // the normal the splat was lit with (point.vert)
layout(location = 2) out vec4 out_normal;
#endif
#ifdef SOFT_SPLATS
// The splat layer's nearest depth (systems/render/splat_layer.h), MIN-blended.
layout(location = 1) out float out_layer_depth;
uniform float u_soft_alpha;  // the Gaussian's peak opacity
flat in float v_opacity;     // the splat's own: less than 1 for a fractional prefix's last
#elif defined(WRITE_ID)
flat in uint v_instance;
layout(location = 1) out uint out_id;  // ID buffer: instance index + 1 (0 = nothing drawn)
#endif

void main() {
#ifdef SOFT_SPLATS
    // exp(-2·|pc|²) over pc in [-1, 1]²: σ is a quarter of the splat's side; its mean over the
    // square is k_soft_splat_kernel_mean (lod/point_line_lod.h).
    vec2 pc = gl_PointCoord * 2.0 - 1.0;
    out_color = vec4(v_color, v_opacity * u_soft_alpha * exp(-2.0 * dot(pc, pc)));
    out_layer_depth = gl_FragCoord.z;
#else
    out_color = vec4(v_color, 1.0);
#ifdef WRITE_NORMAL
    out_normal = vec4(v_lit_normal * 0.5 + 0.5, 1.0);
#endif
#ifdef WRITE_ID
    out_id = v_instance + 1u;
#endif
#endif
}
