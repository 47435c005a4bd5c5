// Behrendt 2005 §3.2: a shell slice is an offset surface of the terrain, generated here from
// the ground's triangles (a static buffer: nothing is uploaded per frame; far tiles use a
// coarser grid of the same samples, components/shell_tile.h), one instance per slice
// of the tile's pyramid level, lifted to the slice's height (lod/shell_levels.h
// shell_slice_height: pairs move together as they merge, §3.3) and slanted toward the viewer by
// the limited Eq. 2 (lod/shell_slanting.h slant_shift): d_i = f · v · (m − x_i) / |v|, held
// within ±f times the reach of the ground's own triangles on the coarser grids.
//
// §3.3's level of detail per triangle: the tile is drawn with the slices of the level its nearest
// point asks (update_shells), and each triangle, from its own centre, may merge further
// (lod/shell_levels.h shell_level_at, mirrored by level_at below, at the distance
// shell_level_distance gives: a vertical offset seen from above shows smaller). A slice its level
// no longer has becomes a point (no fragments), as does a triangle the fragment shader would
// discard whole (outside the tiled area, nearer than the fade). All three vertices decide from
// the centre m (and the triangle's radius), so a triangle is kept or dropped whole.
#include "common.glsl"
layout(location = 0) in vec3 in_position;  // terrain-local
layout(location = 1) in vec3 in_centre;    // the triangle's centre m, terrain-local
layout(location = 2) in float in_radius;   // the largest distance of its vertices from m

const int k_max_levels = 16;
uniform vec3 u_terrain_position;  // camera-relative: the viewer is at -u_terrain_position locally
uniform float u_slice_height;     // the bake's slab thickness h
uniform int u_level;              // the tile's level: each triangle merges at least this far
uniform int u_max_level;          // the pyramid's top level (one slice)
uniform vec3 u_level_criterion;   // pixels per radian, p_min (px), the merge band
uniform int u_level_slices[k_max_levels];       // ⌈S / 2^L⌉
uniform int u_level_first_layer[k_max_levels];  // the level's first layer in a tile's stack
uniform float u_slant;            // f (0: no slanting)
uniform float u_slant_reach;      // the shift is held within ±f times this (lod/shell_slanting.h)
uniform vec2 u_fade;              // shaders/shell.frag's: nothing shows nearer than x metres
uniform vec4 u_area;              // shaders/shell.frag's: the tiled populations' area (terrain-local)

out vec3 v_position;  // camera-relative
out vec2 v_local_xz;
flat out int v_layer;  // in the tile's stack

// lod/shell_levels.h shell_level_at.
void level_at(float distance_m, out int level, out float merge) {
    float lambda = log2(max(distance_m, 1e-3) * u_level_criterion.y / (u_slice_height * u_level_criterion.x));
    level = 0;
    merge = 0.0;
    if (!(lambda > 0.0)) return;
    if (lambda >= float(u_max_level)) { level = u_max_level; return; }
    float whole = floor(lambda);
    float b = clamp(u_level_criterion.z, 1e-6, 1.0);
    level = int(whole);
    merge = clamp((lambda - whole - (1.0 - b)) / b, 0.0, 1.0);
}

// lod/shell_levels.h shell_level_distance.
float level_distance(vec3 eye_to_point) {
    float d = length(eye_to_point);
    return d * d / max(length(eye_to_point.xz), 1e-3 * d);
}

// lod/shell_levels.h shell_slice_height.
float slice_height(int j, int level, float merge, int slices_at_level) {
    float span = u_slice_height * exp2(float(level));
    float centre = (float(j) + 0.5) * span;
    if ((j ^ 1) >= slices_at_level) return centre;
    float pair_centre = float(2 * (j / 2) + 1) * span;
    return centre + merge * (pair_centre - centre);
}

void main() {
    int level;
    float merge;
    level_at(level_distance(in_centre + u_terrain_position), level, merge);
    if (level < u_level) { level = u_level; merge = 0.0; }
    if (level >= u_max_level) merge = 0.0;
    int slices = u_level_slices[level];
    int j = gl_InstanceID;
    v_layer = u_level_first_layer[level] + j;
    v_local_xz = in_position.xz;
    if (j >= slices) {  // merged away at this triangle's level
        v_position = vec3(0.0);
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    vec3 lift = vec3(0.0, slice_height(j, level, merge, slices), 0.0);
    vec3 x = in_position + lift;
    vec3 m = in_centre + lift;
    vec3 v = -u_terrain_position - m;
    float len = length(v);
    float limit = u_slant * u_slant_reach;
    // A triangle the fragment shader would discard whole, wholly nearer than the fade's start or
    // wholly outside the tiled area (slanting moves a point at most `limit`), is not rasterised:
    // all three vertices decide from m and the triangle's radius, so it goes whole.
    float r = in_radius + limit;
    if (len + r < u_fade.x || any(lessThan(m.xz + r, u_area.xy)) || any(greaterThan(m.xz - r, u_area.zw))) {
        v_position = vec3(0.0);
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    x.y += len > 0.0 ? clamp(u_slant * dot(v, m - x) / len, -limit, limit) : 0.0;
    v_position = x + u_terrain_position;
    gl_Position = u_view_projection * vec4(v_position, 1.0);
}
