// The line style (render.style "lines"; Luft 2007 §4 and Figure 7): lines where the normal buffer
// turns or the depth buffer's second difference jumps between neighbouring pixels (after Saito &
// Takahashi 1990's G-buffers), drawn in ink over the finished frame. With the original normals of a crown the
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
    // 1 / distance is linear in screen space across a plane, so its second difference is zero on
    // any plane however grazing (the ground to the horizon) and large at creases and where one
    // surface passes in front of another.
    float w = 1.0 / view_distance(texelFetch(u_depth, p, 0).r);
    float normal_edge = 0.0;
    float depth_edge = 0.0;
    const ivec2 axes[2] = ivec2[2](ivec2(1, 0), ivec2(0, 1));
    for (int i = 0; i < 2; ++i) {
        ivec2 qa = clamp(p + axes[i], ivec2(0), size - 1), qb = clamp(p - axes[i], ivec2(0), size - 1);
        vec4 na = texelFetch(u_normals, qa, 0), nb = texelFetch(u_normals, qb, 0);
        // A surface beside the background: a silhouette.
        if (c.a > 0.5 && (na.a < 0.5 || nb.a < 0.5)) depth_edge = 1.0;
        if (c.a < 0.5 || na.a < 0.5 || nb.a < 0.5) continue;
        float wa = 1.0 / view_distance(texelFetch(u_depth, qa, 0).r);
        float wb = 1.0 / view_distance(texelFetch(u_depth, qb, 0).r);
        depth_edge = max(depth_edge, smoothstep(0.08, 0.2, abs(wa + wb - 2.0 * w) / w));
        // The angle between neighbouring normals (1 - cos).
        vec3 n = normalize(c.xyz * 2.0 - 1.0);
        float turn = max(1.0 - dot(n, normalize(na.xyz * 2.0 - 1.0)), 1.0 - dot(n, normalize(nb.xyz * 2.0 - 1.0)));
        normal_edge = max(normal_edge, smoothstep(0.15, 0.45, turn));
    }
    float line = max(normal_edge, depth_edge);
    if (line <= 0.0) discard;
    out_color = vec4(vec3(0.06, 0.06, 0.07), line);
}
