// The soft splats' visibility pass (lod/point_line_lod.h) writes depth, and this fragment
// shader what the frame's G-buffers need of each visible splat: WRITE_ID the instance it belongs
// to (ID buffer), WRITE_NORMAL the normal it is lit with (the line style's normal buffer,
// edges.frag), so the soft splats' blend pass, which writes neither, leaves them right.
#ifdef WRITE_ID
flat in uint v_instance;
layout(location = 1) out uint out_id;  // ID buffer: instance index + 1 (0 = nothing drawn)
#endif
#ifdef WRITE_NORMAL
flat in vec3 v_lit_normal;  // point.vert
layout(location = 2) out vec4 out_normal;
#endif

void main() {
#ifdef WRITE_ID
    out_id = v_instance + 1u;
#endif
#ifdef WRITE_NORMAL
    out_normal = vec4(v_lit_normal * 0.5 + 0.5, 1.0);
#endif
}
