// Every mesh Sylva draws (terrain, bark, leaves, billboards, point and line samples) is an
// instanced mesh: model vertices from the shared vertex buffer, one instance record
// (resources/draw_list.h instance_gpu: camera-relative position, yaw, scale, tint, fade, texture
// layer) per instance.

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_instance_position_yaw;
layout(location = 4) in vec4 in_instance_scale_tint_fade_layer;
layout(location = 10) in uvec2 in_instance_population;  // 5..9: vertex_transfer.glsl

// The vertex placed by its instance: turned by the yaw (c, s), scaled, moved.
struct instance_pose {
    float c;
    float s;
    mat3 rotation;
    float scale;
    vec3 world;         // camera-relative world position
    vec3 model_normal;  // the vertex's normal in model space (in_normal but for FACING_EYE)
    vec2 uv;            // its texture coordinates (in_uv but for FACING_EYE)
};

// FACING_EYE (material_kind::facing_billboard, the view only): the crossed billboard's pair of
// quads turned about the plant's vertical axis so that one of them faces the eye, the other
// collapsed to a point (its triangles cover nothing). The one shown is the quad whose baked view
// lies nearer the eye's azimuth about the plant: the first quad's (seen from model +z, normal z)
// within 45 degrees of the plant's z axis, the second's (from +x, normal x) within 45 degrees of
// its x axis, either side. The plant is then drawn turned so that quad's front faces the eye: its
// yaw the eye's azimuth (sin : cos = -x : -z of the camera-relative position, the eye at the
// origin; the rotation below takes +z to (sin yaw, 0, cos yaw)), less 90 degrees for the second
// quad, whose front is +x. Its normal and transfer pages turn with it. Straight above the plant
// there is no azimuth: both quads at the plant's own yaw, the crossed billboard.
// The shown quad is then tilted back to the baked elevation nearest the eye's above the plant's
// middle (the facing mesh's normals carry its height as y) and reads that view: models/bake/
// crossed_billboard.h facing_view_plane and its atlas layout, given as FACING_ELEVATIONS (radians)
// and FACING_ELEVATION_S (the atlas's width one elevation's views take; program_table.cpp).
// tests/gl/facing_billboard_gl_test.cpp draws it against the full mesh.
#ifdef FACING_EYE
struct facing_choice {
    float yaw;
    bool shown;     // this vertex's quad is the one shown
    int elevation;  // the index of the baked elevation shown
};
facing_choice face_the_eye(vec3 position, float own_yaw, vec3 model_normal, float middle) {
    vec2 to_eye = -position.xz;
    if (dot(to_eye, to_eye) <= 1e-12) return facing_choice(own_yaw, true, 0);
    float eye_yaw = atan(to_eye.x, to_eye.y);
    float relative = eye_yaw - own_yaw;
    bool second = abs(sin(relative)) > abs(cos(relative));
    bool of_second = abs(model_normal.x) > abs(model_normal.z);
    float elevation = atan(-position.y - middle, length(to_eye));
    int k = 0;  // the nearest: past the midpoint to the next
    for (int i = 1; i < 4; ++i)
        if (elevation > 0.5 * (FACING_ELEVATIONS[i - 1] + FACING_ELEVATIONS[i])) k = i;
    return facing_choice(second ? eye_yaw - 1.5707963267948966 : eye_yaw, second == of_second, k);
}

// A facing quad's vertex (model space: the elevation-0 view's corner, its normal the quad's
// horizontal one) moved onto the view at `elevation`: the plane tilted back about its horizontal
// axis through the plant's `middle`, its edges (top - bottom) / 2 cos e + w sin e above and
// below the middle along the tilted up axis (w the quad's half-width, the vertex's distance from
// the trunk), as the bake drew it; the texture coordinates moved from the elevation-0 cell to
// that view's.
void tilt_facing_vertex(int elevation, float middle, inout vec3 position, inout vec3 normal, inout vec2 uv) {
    float e = FACING_ELEVATIONS[elevation];
    float c = cos(e), s = sin(e);
    vec3 across = vec3(position.x, 0.0, position.z);
    float w = length(across);
    bool top = uv.y < 0.5;
    float v = (position.y - middle) * c + (top ? w * s : -w * s);
    vec3 tilted_up = vec3(0.0, c, 0.0) - normal * s;
    position = across + vec3(0.0, middle, 0.0) + v * tilted_up;
    normal = normal * c + vec3(0.0, s, 0.0);
    uv.x += float(elevation) * FACING_ELEVATION_S;  // two views per elevation
}
#endif

instance_pose pose_instance() {
    instance_pose p;
    float yaw = in_instance_position_yaw.w;
    vec3 position = in_position;
    p.model_normal = in_normal;
    p.uv = in_uv;
    p.scale = in_instance_scale_tint_fade_layer.x;
#ifdef FACING_EYE
    facing_choice facing = face_the_eye(in_instance_position_yaw.xyz, yaw, in_normal, in_normal.y * p.scale);
    yaw = facing.yaw;
    p.model_normal.y = 0.0;
    tilt_facing_vertex(facing.elevation, in_normal.y, position, p.model_normal, p.uv);
#endif
    p.s = sin(yaw);
    p.c = cos(yaw);
    p.rotation = mat3(p.c, 0.0, -p.s, 0.0, 1.0, 0.0, p.s, 0.0, p.c);
    p.world = p.rotation * (position * p.scale) + in_instance_position_yaw.xyz;
#ifdef FACING_EYE
    if (!facing.shown) p.world = in_instance_position_yaw.xyz;
#endif
    return p;
}

// Luft 2007 §5 for a population, kept instanced (components/population_ambient.h, which mirrors
// this): the factor by which the neighbours' density lowers k_a at model-space point q, blended
// trilinearly from the 8 corners of the box [-h, h] x [0, 2h] x [-h, h] packed in the instance.
// Corner c holds 6 bits at bit 6c of the 64-bit word (corner 5 straddles the halves); h is the
// half in bits 48..63. An instance of a scene without populations packs every factor as 1, and
// its programs are built without POPULATION_AMBIENT (program_options::population): the factor is
// then the constant 1, and an implicit-lit vertex costs what a normal-lit one does (Luft 2007's
// "no run-time cost"; components/population_ambient.h promises a scene without populations pays
// nothing for them).
float population_ambient(vec3 q) {
#ifndef POPULATION_AMBIENT
    return 1.0;
#else
    uvec2 p = in_instance_population;
    float h = unpackHalf2x16(p.y >> 16u).x;
    vec3 t = clamp(vec3(0.5 * (q.x / h + 1.0), 0.5 * q.y / h, 0.5 * (q.z / h + 1.0)), 0.0, 1.0);
    float f[8];
    for (int c = 0; c < 8; ++c) {
        int start = 6 * c;
        uint bits = start + 6 <= 32 ? p.x >> uint(start)
                  : start >= 32     ? p.y >> uint(start - 32)
                                    : (p.x >> uint(start)) | (p.y << uint(32 - start));
        f[c] = float(bits & 63u) / 63.0;
    }
    vec4 lower = mix(vec4(f[0], f[2], f[4], f[6]), vec4(f[1], f[3], f[5], f[7]), t.x);  // along x
    vec2 middle = mix(lower.xz, lower.yw, t.y);                                         // along y
    return mix(middle.x, middle.y, t.z);                                                // along z
#endif
}
