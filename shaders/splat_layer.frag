// Draws the soft splats' layer (systems/render/splat_layer.h) over the frame: its colour
// filtered up (premultiplied, blended with ONE, ONE_MINUS_SRC_ALPHA), at the nearest splat depth
// of the 2x2 texels the filter reads, so the frame's depth test keeps what lies in front of the
// splats. WRITE_ID / WRITE_NORMAL: the pass after it, which writes the ID of a visibility splat
// among those texels and the normal of the nearest one (the line style's normal buffer,
// edges.frag), and nothing else. Where there is none (no splat, or only the rim of a Gaussian
// wider than the visibility splats) it discards, so the pixel keeps the ID and normal of what
// lies behind, as with splats drawn straight into the frame: these buffers are not blended, and
// a fragment cannot keep one output and write another.
in vec2 v_ndc;
layout(binding = 1) uniform sampler2D u_layer_depth;
#if defined(WRITE_ID) || defined(WRITE_NORMAL)
#define VISIBILITY
#endif
#ifdef WRITE_ID
layout(binding = 2) uniform usampler2D u_layer_ids;
layout(location = 1) out uint out_id;
#endif
#ifdef WRITE_NORMAL
layout(binding = 3) uniform sampler2D u_layer_normals;  // alpha 1 where a visibility splat wrote
layout(location = 2) out vec4 out_normal;
#endif
#ifndef VISIBILITY
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
#endif
#ifdef WRITE_NORMAL
    // The four texels textureGather read, in its order (i0 j1, i1 j1, i1 j0, i0 j0): the normal
    // of the written one whose splats lie nearest.
    ivec2 size = textureSize(u_layer_normals, 0);
    ivec2 base = ivec2(floor(uv * vec2(size) - 0.5));
    const ivec2 offsets[4] = ivec2[4](ivec2(0, 1), ivec2(1, 1), ivec2(1, 0), ivec2(0, 0));
    float nearest = 2.0;
    vec4 normal = vec4(0.0);
    for (int i = 0; i < 4; ++i) {
        vec4 n = texelFetch(u_layer_normals, clamp(base + offsets[i], ivec2(0), size - 1), 0);
        if (n.a > 0.5 && depths[i] < nearest) {
            nearest = depths[i];
            normal = n;
        }
    }
    if (normal.a < 0.5) discard;
    out_normal = normal;
#endif
#ifndef VISIBILITY
    out_color = texture(u_layer_color, uv);
#endif
}
