// Draws the shells' layer (systems/render/passes/shell_pass.h) over the frame: its premultiplied
// colour filtered up (blended with ONE, ONE_MINUS_SRC_ALPHA, Behrendt 2005 §3.3's modified
// equation once more), at the nearest slice depth of the 2x2 texels the filter reads, so the
// frame's depth test keeps what lies in front of the shells. WRITE_ID: the pass after it, which
// writes the shells' ID (resources/draw_list.h k_shell_id) where the layer covers at least half
// the pixel, so the coverage metric sees the plants the shells show, and nothing else.
in vec2 v_ndc;
layout(binding = 0) uniform sampler2D u_layer_color;
layout(binding = 1) uniform sampler2D u_layer_depth;
#ifdef WRITE_ID
layout(location = 1) out uint out_id;
#else
layout(location = 0) out vec4 out_color;
#endif

void main() {
    vec2 uv = v_ndc * 0.5 + 0.5;
    vec4 depths = textureGather(u_layer_depth, uv, 0);
    float nearest = min(min(depths.x, depths.y), min(depths.z, depths.w));
    if (nearest >= 1.0) discard;  // no slice here
    gl_FragDepth = nearest;
#ifdef WRITE_ID
    if (texture(u_layer_color, uv).a < 0.5) discard;
    out_id = 0xffffffffu;
#else
    out_color = texture(u_layer_color, uv);
#endif
}
