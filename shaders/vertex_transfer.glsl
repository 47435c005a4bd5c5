// The per-vertex SH transfer streamed beside the vertices (models/mesh.h vertex_transfer,
// Behrendt 2005 §4): 9 halves for the side the normal faces, 9 for the other. Needs
// common.glsl and transfer.glsl first.

layout(location = 5) in vec4 in_transfer0;
layout(location = 6) in vec4 in_transfer1;
layout(location = 7) in vec4 in_transfer2;
layout(location = 8) in vec4 in_transfer3;
layout(location = 9) in vec4 in_transfer4;

// Both sides' transfer, turned by the instance's yaw (c, s) into the world.
void turned_transfer(float c, float s, out float front[9], out float back[9]) {
    front = float[9](in_transfer0.x, in_transfer0.y, in_transfer0.z, in_transfer0.w, in_transfer1.x,
                     in_transfer1.y, in_transfer1.z, in_transfer1.w, in_transfer2.x);
    back = float[9](in_transfer2.y, in_transfer2.z, in_transfer2.w, in_transfer3.x, in_transfer3.y,
                    in_transfer3.z, in_transfer3.w, in_transfer4.x, in_transfer4.y);
    sh_rotate_about_y(front, c, s);
    sh_rotate_about_y(back, c, s);
}
