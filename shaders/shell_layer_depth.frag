// The shell layer's depth (systems/render/passes/shell_pass.h): the farthest of the 2x2 frame depths
// under each layer texel, so a slice is hidden only where the terrain or a plant covers all four.
in vec2 v_ndc;
layout(binding = 0) uniform sampler2D u_frame_depth;

void main() {
    ivec2 base = ivec2(gl_FragCoord.xy) * 2;
    ivec2 last = textureSize(u_frame_depth, 0) - 1;
    float d = texelFetch(u_frame_depth, min(base, last), 0).r;
    d = max(d, texelFetch(u_frame_depth, min(base + ivec2(1, 0), last), 0).r);
    d = max(d, texelFetch(u_frame_depth, min(base + ivec2(0, 1), last), 0).r);
    d = max(d, texelFetch(u_frame_depth, min(base + ivec2(1, 1), last), 0).r);
    gl_FragDepth = d;
}
