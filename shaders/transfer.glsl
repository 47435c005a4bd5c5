// Precomputed radiance transfer (Behrendt 2005 §4, after Sloan, Kautz and Snyder 2002): each
// vertex, point, line end or cloud texel carries two 9-coefficient SH transfer vectors baked
// from the full plant with its self-shadowing (models/bake/radiance_transfer.h): one for light
// arriving on the side its normal faces, one for the other side. Shading is "the scalar product
// of the coefficients" with the environment's radiance coefficients: the sky (u_sh_radiance)
// and the sun as a directional light (u_sun_sh: the basis at the sun's direction; its colour is
// u_sun_radiance). Every representation of a plant reads the same coefficients, so a plant is
// lit alike at every distance. Needs common.glsl first.

// Per species, by texture layer (systems/render/scene_textures.cpp make_species_block): x the
// centre height of a sphere around every representation of the plant (scale 1), y its radius,
// z the species' first layer in the transfer-page arrays. Shadows between objects (Behrendt
// 2005 §4: "we use a shadow map") are looked up from where the sun's ray leaves the plant's own
// sphere, so the map adds the shadows of other objects and not a second, sharper copy of the
// self-shadowing the transfer already holds.
layout(std140, binding = 1) uniform species_block {
    vec4 u_species[64];
};

// An eco-tile point set's instance (Deussen 2002 §6.2) marks its layer with this fraction
// (resources/draw_list.h k_aggregated_layer_flag): its samples come from many plants, so there is
// no one sphere to leave.
bool aggregated_layer(float layer) { return fract(layer) > 0.125; }

// The plant's sphere, camera-relative centre and radius, for an instance at `origin`
// (camera-relative) with `scale`; radius -1 for an aggregated set.
vec4 plant_sphere(vec3 origin, float scale, float layer) {
    if (aggregated_layer(layer)) return vec4(0.0, 0.0, 0.0, -1.0);
    vec4 s = u_species[int(layer + 0.5)];
    return vec4(origin + vec3(0.0, s.x * scale, 0.0), s.y * scale);
}

// How far the sun's ray from `position` (camera-relative) runs inside `sphere`; -1 when there
// is no sphere (the caller then leaves the shadow map out: an aggregated set keeps only the
// self-shadowing its transfer holds).
float sphere_exit_distance(vec3 position, vec4 sphere) {
    if (sphere.w < 0.0) return -1.0;
    vec3 d = position - sphere.xyz;
    float b = dot(d, u_sun_direction.xyz);
    float disc = b * b - (dot(d, d) - sphere.w * sphere.w);
    return disc > 0.0 ? max(-b + sqrt(disc), 0.0) : 0.0;
}

// Mirrors sylva::rotate_about_y (lighting/transfer_rotation.h, where it is derived):
// model-space coefficients to world space under the instance yaw, c = cos, s = sin.
void sh_rotate_about_y(inout float t[9], float c, float s) {
    const float sqrt3 = 1.7320508;
    float t2 = t[2], t3 = t[3], t4 = t[4], t5 = t[5], t6 = t[6], t7 = t[7], t8 = t[8];
    t[2] = c * t2 - s * t3;
    t[3] = s * t2 + c * t3;
    t[4] = c * t4 + s * t5;
    t[5] = -s * t4 + c * t5;
    t[6] = (c * c - 0.5 * s * s) * t6 - sqrt3 * c * s * t7 + 0.5 * sqrt3 * s * s * t8;
    t[7] = sqrt3 * c * s * t6 + (c * c - s * s) * t7 - c * s * t8;
    t[8] = 0.5 * sqrt3 * s * s * t6 + c * s * t7 + (1.0 - 0.5 * s * s) * t8;
}

// The transfer pages' texel layout (models/bake/transfer_pages.h, mirrored): five RGBA8 pages,
// coefficients 0..8 of the side seen then 9..17 of the other, each (T / range) * 0.5 + 0.5.
// Billboard atlases (transfer_pages.glsl) and shell slices (shell.frag, shell_relight.comp) alike.
const float k_transfer_page_range = 1.25;
void decode_transfer_page(int page, vec4 texel, inout float seen[9], inout float other[9]) {
    vec4 t = (texel * 2.0 - 1.0) * k_transfer_page_range;
    for (int k = 0; k < 4; ++k) {
        int i = 4 * page + k;
        if (i < 9) seen[i] = t[k];
        else if (i < 18) other[i - 9] = t[k];
    }
}

// Sky light through the transfer: sum_i T_i L_i per channel (irradiance-like: the albedo/pi
// is applied by the caller).
vec3 sh_transfer_sky(float t[9]) {
    vec3 e = vec3(0.0);
    for (int i = 0; i < 9; ++i) e += t[i] * u_sh_radiance[i].rgb;
    return e;
}

// The sun through the transfer, per unit of its irradiance: sum_i T_i Y_i(l).
float sh_transfer_sun(float t[9]) {
    float e = 0.0;
    for (int i = 0; i < 9; ++i) e += t[i] * u_sun_sh[i / 4][i % 4];
    return e;
}
