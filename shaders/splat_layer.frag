// Draws the soft splats' layer (systems/render/splat_layer.h) over the frame: its colour
// filtered up (premultiplied, blended with ONE, ONE_MINUS_SRC_ALPHA), at the nearest splat depth
// of the 2x2 texels the filter reads, so the frame's depth test keeps what lies in front of the
// splats. WRITE_ID: also the ID of a visibility splat among those texels (the frame's ID buffer
// is not blended, so a pixel the layer leaves untouched is discarded to keep its own).
in vec2 v_ndc;
layout(binding = 0) uniform sampler2D u_layer_color;
layout(binding = 1) uniform sampler2D u_layer_depth;
layout(location = 0) out vec4 out_color;
#ifdef WRITE_ID
layout(binding = 2) uniform usampler2D u_layer_ids;
layout(location = 1) out uint out_id;
#endif

void main() {
    vec2 uv = v_ndc * 0.5 + 0.5;
    vec4 depths = textureGather(u_layer_depth, uv, 0);
    gl_FragDepth = min(min(depths.x, depths.y), min(depths.z, depths.w));
    out_color = texture(u_layer_color, uv);
#ifdef WRITE_ID
    uvec4 ids = textureGather(u_layer_ids, uv, 0);
    uint id = max(max(ids.x, ids.y), max(ids.z, ids.w));
    if (id == 0u && out_color.a < 0.5 / 255.0) discard;  // nothing of the layer here
    out_id = id;
#endif
}
