// Behrendt 2005 §3.2: a shell slice is an offset surface of the terrain, generated here from
// the ground's triangles (a static buffer: nothing is uploaded per frame), one instance per slice
// of the tile's pyramid level, lifted to the slice's height (lod/shell_levels.h
// shell_slice_height: pairs move together as they merge, §3.3) and slanted toward the viewer by
// the limited Eq. 2 (lod/shell_slanting.h slant_shift): d_i = f · v · (m − x_i) / |v|.
#include "common.glsl"
layout(location = 0) in vec3 in_position;  // terrain-local
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec3 in_centre;    // the triangle's centre m, terrain-local

uniform vec3 u_terrain_position;  // camera-relative: the viewer is at -u_terrain_position locally
uniform float u_slice_height;     // the bake's slab thickness h
uniform int u_level;              // L: slices of 2^L slabs
uniform float u_merge;            // t: how far each pair of level L has moved together
uniform int u_slices_at_level;
uniform float u_slant;            // f (0: no slanting)

out vec3 v_position;  // camera-relative
out vec2 v_local_xz;
flat out int v_slice;

float slice_height(int j) {
    float span = u_slice_height * exp2(float(u_level));
    float centre = (float(j) + 0.5) * span;
    if ((j ^ 1) >= u_slices_at_level) return centre;
    float pair_centre = float(2 * (j / 2) + 1) * span;
    return centre + u_merge * (pair_centre - centre);
}

void main() {
    int j = gl_InstanceID;
    vec3 lift = vec3(0.0, slice_height(j), 0.0);
    vec3 x = in_position + lift;
    vec3 m = in_centre + lift;
    vec3 v = -u_terrain_position - m;
    float len = length(v);
    x.y += len > 0.0 ? u_slant * dot(v, m - x) / len : 0.0;
    v_position = x + u_terrain_position;
    v_local_xz = in_position.xz;
    v_slice = j;
    gl_Position = u_view_projection * vec4(v_position, 1.0);
}
