// Shared declarations. Mirrors systems/render/frame_uniforms.h (std140; the C++ side
// static_asserts every offset) and resources/draw_list.h instance_gpu (instanced attributes).

layout(std140, binding = 0) uniform frame_block {
    mat4 u_view;                       // camera-relative: the eye is at the origin
    mat4 u_projection;
    mat4 u_view_projection;
    mat4 u_inverse_view_projection;
    mat4 u_cascade_view_projection[4];
    vec4 u_cascade_split_far;          // view-space far distance of each cascade
    vec4 u_sun_direction;              // xyz towards the sun; w: 1 when shadows are on
    vec4 u_sun_radiance;               // rgb sun colour times intensity; w: cascade count
    vec4 u_sh_irradiance[9];           // rgb per coefficient: irradiance SH (3 bands)
    vec4 u_fog;                        // rgb fog colour; w density per metre
    vec4 u_params;                     // x exposure, y shadow texel size (uv), z time s, w ground uv scale
    vec4 u_cascade_texel_world;        // world size of one shadow texel per cascade
    vec4 u_sh_radiance[9];             // rgb per coefficient: the sky's radiance SH (transfer.glsl)
    vec4 u_sun_sh[3];                  // the 9 SH basis values at the sun's direction
    vec4 u_terrain_map;                // (xz offset, scale, half texel): camera-relative xz -> uv
    vec4 u_terrain_params;             // x height offset, y shadow edge m, z shadow on, w normals on
};

// Ramamoorthi & Hanrahan 2001: irradiance E(n) from 9 SH coefficients. The coefficients are
// already convolved with the clamped cosine on the CPU (lighting/spherical_harmonics),
// so evaluating the basis is all that is left. Basis constants: Sloan 2008.
vec3 sh_irradiance(vec3 n) {
    vec3 e = u_sh_irradiance[0].rgb * 0.282095;
    e += u_sh_irradiance[1].rgb * (0.488603 * n.y);
    e += u_sh_irradiance[2].rgb * (0.488603 * n.z);
    e += u_sh_irradiance[3].rgb * (0.488603 * n.x);
    e += u_sh_irradiance[4].rgb * (1.092548 * n.x * n.y);
    e += u_sh_irradiance[5].rgb * (1.092548 * n.y * n.z);
    e += u_sh_irradiance[6].rgb * (0.315392 * (3.0 * n.z * n.z - 1.0));
    e += u_sh_irradiance[7].rgb * (1.092548 * n.x * n.z);
    e += u_sh_irradiance[8].rgb * (0.546274 * (n.x * n.x - n.y * n.y));
    return max(e, vec3(0.0));
}

// Narkowicz 2015, "ACES filmic tone mapping curve", then display gamma.
vec3 tone_map(vec3 hdr) {
    // The curve reaches 1 at x ~ 7.2; clamping far above that changes no pixel but keeps x * x
    // finite for any radiance (inf / inf would be NaN).
    vec3 x = min(hdr * u_params.x, vec3(1e4));
    vec3 mapped = clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
    return pow(mapped, vec3(1.0 / 2.2));
}

// Exponential fog towards the horizon colour: distant hills recede (aerial perspective).
vec3 apply_fog(vec3 color, float distance_m) {
    float f = 1.0 - exp(-distance_m * u_fog.w);
    return mix(color, u_fog.rgb, f);
}
