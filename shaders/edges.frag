// The line style (render.style "lines"; Luft 2007 §4 and Figure 7): lines where the normal buffer
// or the depth buffer jumps between neighbouring pixels (after Saito & Takahashi 1990's
// G-buffers), drawn in ink over the finished frame. With the original normals of a crown the
// normal buffer jumps leaf by leaf and the lines clutter; with normals realigned to the foliage's
// implicit surface (--lighting implicit) only its outline and folds remain.
#include "common.glsl"
in vec2 v_ndc;
layout(binding = 0) uniform sampler2D u_normals;  // surface_inputs.glsl out_normal
layout(binding = 1) uniform sampler2D u_depth;    // the frame's depth attachment
layout(location = 0) out vec4 out_color;

// Distance from the eye along the view axis of a depth-buffer value (perspective projection).
float view_distance(float depth) {
    return u_projection[3][2] / ((depth * 2.0 - 1.0) + u_projection[2][2]);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(u_normals, 0);
    vec4 c = texelFetch(u_normals, p, 0);
    float d = view_distance(texelFetch(u_depth, p, 0).r);
    float normal_edge = 0.0;
    float depth_edge = 0.0;
    const ivec2 offsets[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
    for (int i = 0; i < 4; ++i) {
        ivec2 q = clamp(p + offsets[i], ivec2(0), size - 1);
        vec4 nb = texelFetch(u_normals, q, 0);
        float dn = view_distance(texelFetch(u_depth, q, 0).r);
        // A surface beside the background, or beside a surface much farther: a silhouette.
        if ((c.a > 0.5) != (nb.a > 0.5)) depth_edge = 1.0;
        else if (c.a > 0.5) depth_edge = max(depth_edge, smoothstep(0.04, 0.12, abs(dn - d) / min(d, dn)));
        // Both surfaces: the angle between their normals (1 - cos).
        if (c.a > 0.5 && nb.a > 0.5) {
            vec3 a = c.xyz * 2.0 - 1.0, b = nb.xyz * 2.0 - 1.0;
            normal_edge = max(normal_edge, smoothstep(0.15, 0.45, 1.0 - dot(normalize(a), normalize(b))));
        }
    }
    float line = max(normal_edge, depth_edge);
    if (line <= 0.0) discard;
    out_color = vec4(vec3(0.06, 0.06, 0.07), line);
}
