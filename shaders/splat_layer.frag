// Draws the soft splats' layer (systems/render/splat_layer.h) over the frame: its colour
// filtered up (premultiplied, blended with ONE, ONE_MINUS_SRC_ALPHA), at the nearest splat depth
// of the 2x2 texels the filter reads, so the frame's depth test keeps what lies in front of the
// splats. WRITE_ID: the ID pass after it, which writes the ID of a visibility splat among those
// texels and nothing else. Where there is none (no splat, or only the rim of a Gaussian wider
// than the visibility splats) it discards, so the pixel keeps the ID of what lies behind, as
// with splats drawn straight into the frame: the ID buffer is not blended, and a fragment
// cannot keep one output and write another.
in vec2 v_ndc;
layout(binding = 1) uniform sampler2D u_layer_depth;
#ifdef WRITE_ID
layout(binding = 2) uniform usampler2D u_layer_ids;
layout(location = 1) out uint out_id;
#else
layout(binding = 0) uniform sampler2D u_layer_color;
layout(location = 0) out vec4 out_color;
#endif

void main() {
    vec2 uv = v_ndc * 0.5 + 0.5;
    vec4 depths = textureGather(u_layer_depth, uv, 0);
    gl_FragDepth = min(min(depths.x, depths.y), min(depths.z, depths.w));
#ifdef WRITE_ID
    uvec4 ids = textureGather(u_layer_ids, uv, 0);
    uint id = max(max(ids.x, ids.y), max(ids.z, ids.w));
    if (id == 0u) discard;
    out_id = id;
#else
    out_color = texture(u_layer_color, uv);
#endif
}
