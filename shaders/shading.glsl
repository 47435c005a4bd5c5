// Sun and sky shading shared by mesh.frag, cloud.frag and line.frag (per fragment) and
// point.vert (per point: a splat is one sample, so its colour is computed once, where the
// vertex is, and every fragment of the splat takes it -- on llvmpipe, which shades fragments in
// 4x4 blocks, a one-pixel splat's fragment shader costs as much as sixteen pixels').
// Needs common.glsl first.

layout(binding = 1) uniform sampler2DArrayShadow u_shadow_map;

// True where the cascades hold shadows: with shadows on, nearer than the last cascade's far end
// (beyond it nothing shades anything but the terrain). The one rule for the cascades' reach:
// cascade_sun_visibility is 1 outside it, and shaders/shell.frag's canopy shade holds only inside.
bool within_cascades_at(float view_depth) {
    return u_sun_direction.w >= 0.5 && view_depth <= u_cascade_split_far[int(u_sun_radiance.w) - 1];
}
bool within_cascades(vec3 position) {
    return within_cascades_at(-(u_view * vec4(position, 1.0)).z);
}

// Cascade chosen by view depth; four hardware-PCF taps half a texel off centre, each a bilinear
// 2x2 compare, together a smooth 3x3-texel footprint (a software rasteriser pays per tap). The
// sample is pushed along the normal by about one texel to avoid acne on slopes.
// SHADOW_SINGLE_TAP (point splats, shaded once per sample in point.vert): one bilinear tap at
// the centre. The 3x3 filter smooths a shadow's edge across neighbouring pixels of one surface;
// a splat's neighbours are other random samples, so it smooths nothing there. On landscape
// (6 frames, soft splats, d' = 3 and 2.5 without fog weighting) it moved popping from 3.561 to
// 3.563 and 3.375 to 3.376, SSIM and FLIP by 0.0001, and saved 3.5 of the 40 ms of CPU per frame
// that llvmpipe's vertex stage spent at d' = 3 (perf, 22 frames less 2, two runs each).
float cascade_sun_visibility(vec3 position, vec3 normal, float view_depth) {
    if (!within_cascades_at(view_depth)) return 1.0;
    int count = int(u_sun_radiance.w);
    int cascade = count - 1;
    for (int i = 0; i < count; ++i) {
        if (view_depth < u_cascade_split_far[i]) { cascade = i; break; }
    }
    vec3 offset_position = position + normal * (1.5 * u_cascade_texel_world[cascade]);
    vec4 light = u_cascade_view_projection[cascade] * vec4(offset_position, 1.0);
    vec3 p = light.xyz / light.w * 0.5 + 0.5;
    if (any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)))) return 1.0;
    float texel = u_params.y;
    float bias = 0.0005;
#ifdef SHADOW_SINGLE_TAP
    return texture(u_shadow_map, vec4(p.xy, float(cascade), p.z - bias));
#else
    float sum = 0.0;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            sum += texture(u_shadow_map, vec4(p.xy + (vec2(x, y) - 0.5) * texel, float(cascade), p.z - bias));
    return sum * 0.25;
#endif
}

// The terrain's shadow (lighting/terrain_shadow.h): a point is in it when its height above the
// ground is below the shadow's depth there, read from the (height, depth) texture bilinearly;
// the light comes back over `edge` metres above the shadow's top. At any distance, so the
// cascades' far end does not cut the hills' shadows off. Clamped at the ground: a coarser ground
// grid (components/ground_tile.h) may lie a little below the terrain's samples, and it is lit
// where the terrain is.
layout(binding = 10) uniform sampler2D u_terrain_shadow_map;

float terrain_sun_visibility(vec3 position) {
    if (u_terrain_params.z < 0.5) return 1.0;
    vec2 uv = (position.xz + u_terrain_map.xy) * u_terrain_map.z + u_terrain_map.w;
    if (any(lessThan(uv, vec2(u_terrain_map.w))) || any(greaterThan(uv, vec2(1.0 - u_terrain_map.w))))
        return 1.0;
    vec2 ground = texture(u_terrain_shadow_map, uv).rg;  // height, shadow depth above it
    float above = max(position.y + u_terrain_params.x - ground.x, 0.0);
    return clamp((above - ground.y) / u_terrain_params.y + 1.0, 0.0, 1.0);
}

// The sun's visibility: the shadow cascades' (other objects) times the terrain's.
float sun_visibility(vec3 position, vec3 normal, float view_depth) {
    return cascade_sun_visibility(position, normal, view_depth) * terrain_sun_visibility(position);
}

// Display colour of a surface point: albedo `base`, unit normal `n` (already facing the side
// seen), camera-relative `position`. Sun with cascaded shadows plus SH sky light; `foliage`
// adds sunlight transmitted through the blade when it is lit from behind. Then fog and tone
// mapping.
// STYLE_TOON (Luft 2007 §4, cartoon shading after Decaudin 1996): a light term in [0, 1]
// quantised to three bands, 0, 1/2 and 1, with a soft edge a tenth of a band wide.
float toon_band(float x) {
    float bands = 2.0;
    float f = x * bands;
    float edge = fract(f);
    return (floor(f) + smoothstep(0.45, 0.55, edge)) / bands;
}

// A normal filtered from a normal page (a bake's blur, mip levels), lit as it comes rather than
// made unit again (Toksvig 2005): the mean of many leaves' normals is shorter the more they
// disagree, and kept short, the sky's SH irradiance and the sun's term fall toward their means
// over the spread; renormalised, the mean lights a crown as one smooth surface, brighter than its
// leaves. Only held to unit length at most (8-bit rounding can make it a little longer).
vec3 filtered_normal(vec3 n) {
    return n * min(1.0, 1.0 / max(length(n), 1e-4));
}

// The share of the sun's light left by a canopy above the point, which the shadow map does not
// hold: the shells' slices above a slice (lod/shell_canopy.h; set by shaders/shell.frag), 1 for
// everything else.
float sun_transmittance = 1.0;

// The sun's clamped cosine E[max(n.l, 0)] over the leaves a filtered normal averages, from the
// mean mu = n.l and the spread w = 1 - |n|; mirrors sylva::filtered_clamped_cosine
// (lighting/filtered_normal.h, where it is derived and tested). Lit with max(mu, 0) instead, the
// billboards, clouds and shells came out greyer than their leaves: on landscape (12 frames,
// 480x270) the crossed billboards' FLIP fell from 0.0467 to 0.0460 with it, SSIM rose from
// 0.8844 to 0.8855; on forest every configuration's SSIM rose and FLIP fell.
float filtered_clamped_cosine(float mu, float w) {
    if (mu >= w) return mu;
    if (mu <= -w) return 0.0;
    return (mu + w) * (mu + w) / (4.0 * w);
}

// `ambient` scales the sky's light: Luft 2007 Eq. 1's k_a (1 but under IMPLICIT_LIGHTING).
vec3 shade_surface_ambient(vec3 base, vec3 n, vec3 position, bool foliage, float ambient) {
    vec3 l = u_sun_direction.xyz;
    float view_depth = -(u_view * vec4(position, 1.0)).z;
    float visibility = sun_visibility(position, n, view_depth);
    float n_dot_l = dot(n, l);
#ifdef STYLE_TOON
    // The sun's term and k_a in bands; the sky's colour from above, the same for every normal.
    n_dot_l = toon_band(max(n_dot_l, 0.0) * visibility);
    visibility = 1.0;
    ambient = 0.25 + 0.75 * toon_band(ambient);
    vec3 sky = ambient * sh_irradiance(vec3(0.0, 1.0, 0.0));
#else
    vec3 sky = ambient * sh_irradiance(n);
#endif
    vec3 sun = u_sun_radiance.rgb * visibility * sun_transmittance;
#ifdef STYLE_TOON
    float facing_sun = n_dot_l;  // already a band in [0, 1]
#else
    float facing_sun = filtered_clamped_cosine(n_dot_l, 1.0 - min(length(n), 1.0));
#endif
    vec3 radiance = base / 3.14159265 * (sky + sun * facing_sun);
    if (foliage) radiance += base * vec3(0.9, 1.0, 0.5) / 3.14159265 * sun * (0.35 * (facing_sun - n_dot_l));
    vec3 color = apply_fog(radiance, length(position));
    return tone_map(color);
}

vec3 shade_surface(vec3 base, vec3 n, vec3 position, bool foliage) {
    return shade_surface_ambient(base, n, position, foliage, 1.0);
}

// Luft 2007 §3.2 end: the baked normal's length is the ambient coefficient k_a, and its direction
// the normal realigned to the foliage's implicit surface (§3.3), which lights the crown by its
// shape: it is not turned toward the side seen, as a thin card's own normal is.
vec3 shade_implicit(vec3 base, vec3 encoded_normal, vec3 position, bool foliage) {
    float ka = length(encoded_normal);
    vec3 n = ka > 0.0 ? encoded_normal / ka : vec3(0.0, 1.0, 0.0);
    return shade_surface_ambient(base, n, position, foliage, min(ka, 1.0));
}

// A colour already lit at bake time (a light factor of 1 where it faced the bake's light
// unshadowed) under this scene's light level: the sky's irradiance on an upward surface plus
// the sun's, then fog and tone mapping.
vec3 shade_pre_lit(vec3 lit, vec3 position) {
    vec3 irradiance = sh_irradiance(vec3(0.0, 1.0, 0.0)) + u_sun_radiance.rgb;
    vec3 color = apply_fog(lit / 3.14159265 * irradiance, length(position));
    return tone_map(color);
}

// Luft 2007's k_a under SH transfer (lighting "sh_implicit"): the caller sets it from the normal's
// length before shading; it scales the sky's light (the transfer's own self-shadowing stays).
float sh_ambient = 1.0;

// Precomputed radiance transfer (transfer.glsl; Behrendt 2005 §4): `sky_seen` = T_seen . L_sky,
// `sun_seen` = T_seen . Y(l) and `sun_other` = T_other . Y(l), so the plant's self-shadowing is in
// the coefficients. Shadows of other objects come from the shadow map, looked up where the sun's
// ray leaves the plant's own sphere (`exit` metres towards the sun; negative: no shadow map, see
// transfer.glsl sphere_exit_distance). Foliage transmits the sunlight that reaches its other
// side, as shade_surface's leaves do.
vec3 shade_transfer(vec3 base, vec3 sky_seen, float sun_seen, float sun_other, vec3 position, float exit,
                    bool foliage) {
    vec3 l = u_sun_direction.xyz;
    float view_depth = -(u_view * vec4(position, 1.0)).z;
    float visibility = exit < 0.0 ? terrain_sun_visibility(position) : sun_visibility(position + l * exit, l, view_depth);
#ifdef STYLE_TOON
    sun_seen = toon_band(clamp(sun_seen, 0.0, 1.0) * visibility);
    sun_other = 0.0;
    visibility = 1.0;
#endif
    vec3 sun = u_sun_radiance.rgb * visibility;
    vec3 radiance = base / 3.14159265 * (sh_ambient * max(sky_seen, vec3(0.0)) + sun * max(sun_seen, 0.0));
    if (foliage) radiance += base * vec3(0.9, 1.0, 0.5) / 3.14159265 * sun * (0.35 * max(sun_other, 0.0));
    vec3 color = apply_fog(radiance, length(position));
    return tone_map(color);
}
