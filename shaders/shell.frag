// Behrendt 2005 §3.3–3.4: a shell slice's fragment finds its Wang tile in the index texture from
// its terrain position, reads that tile's slice of the current pyramid level (premultiplied
// colour and the normal seen from above), lights it like the plants (sun with the cascades'
// shadows, sky, fog; under SH_TRANSFER by the SH transfer baked into the slices, §4, as the
// SH-lit plants are, its sums with this light made ahead by shaders/shell_relight.comp) and is
// blended with the modified equation c + F·(1 − α) (GL_ONE,
// GL_ONE_MINUS_SRC_ALPHA), bottom slice first. Near the viewer it fades out where the plants'
// ladder hands over to it (§3.3 end: a linear fade over the band). Drawn into the shell layer
// (systems/render/passes/shell_pass.h), it also writes its window depth for the layer's composite.
#include "common.glsl"
#include "shading.glsl"
#if defined(SH_TRANSFER) && defined(SHELL_RELIT)
// The slices' SH transfer summed with this light (shaders/shell_relight.comp, run once the light
// holds still; the colour's layers at the transfer's resolution): rgb T_seen . L_sky and a
// T_seen . Y(sun) for the side facing up, r T_other . Y(sun) for the other.
layout(binding = 5) uniform sampler2DArray u_lit_seen;
layout(binding = 6) uniform sampler2DArray u_lit_other;
#elif defined(SH_TRANSFER)
#include "transfer.glsl"
// The slices' transfer, one array per page (models/bake/shell_bake.h shell_stack::transfer; its
// layers are the colour's), each coefficient (T / range) * 0.5 + 0.5: 0..8 the side facing up,
// 9..17 the other, world space (the bake turned each plant's by its yaw). Summed here with a
// light that changes every frame.
layout(binding = 5) uniform sampler2DArray u_shell_transfer[5];
#endif
// The depth test before the shader: a slice behind the ground or a plant costs no shading (the
// pass writes no depth, so testing first changes nothing else).
layout(early_fragment_tests) in;
in vec3 v_position;
in vec2 v_local_xz;
flat in int v_layer;  // in the tile's stack: the level's first layer + the slice

layout(binding = 2) uniform sampler2DArray u_shell_colour;
#ifndef SH_TRANSFER
layout(binding = 3) uniform sampler2DArray u_shell_normal;
#endif
layout(binding = 4) uniform usampler2D u_wang_index;
uniform vec4 u_lattice;  // xy: lattice corner (0, 0), terrain-local; z: tile size; w: 1 / tile size
uniform int u_layers_per_tile;
uniform vec2 u_fade;  // the shell is transparent nearer than x metres, whole beyond y
uniform int u_premultiplied;  // 0: straight colour, the standard equation (measurement only)
uniform vec4 u_area;  // x0, z0, x1, z1: where the tiled populations grow (terrain-local)
// The colour's footprint against the one the derivatives give: 0.5 when drawn into the half-size
// layer (systems/render/passes/shell_pass.h), whose composite filters it up bilinearly. Fetched
// at the layer texel's own footprint the colour was filtered twice, by the mips at the layer's
// scale and by the composite, and the far field blurred; at a frame pixel's footprint (half a
// layer texel's) the composite alone filters at the layer's scale. On docs/measure_shells.py's
// far fields (1 frame, 480x270) SSIM 0.9594/0.9472/0.9367 became 0.9606/0.9480/0.9390 at
// 5°/10°/20°, FLIP 0.0399/0.0389/0.0408 became 0.0380/0.0378/0.0397, landscape's 0.9839 0.9849;
// a quarter measured no better (0.9604/0.9476/0.9382), and drawn straight into the frame a half
// lowered SSIM (0.9535 to 0.9521 at 5°: aliasing), so there it stays 1. The lighting's fetches
// keep the whole footprint: they vary slowly and the normal's length is its spread (Toksvig).
uniform float u_footprint_scale;

layout(location = 0) out vec4 out_color;
layout(location = 1) out float out_nearest;  // the shell layer's nearest slice (MIN-blended)

// lod/shell_sampling.h: the footprint cut into at most this many fetches, a slab's path held to
// this many thicknesses.
const int k_max_taps = 4;
const float k_max_path = 32.0;

// The layer of this fragment's slice in the stack of the Wang tile under cell coordinate p.
float slice_layer(vec2 p) {
    ivec2 cells = textureSize(u_wang_index, 0);
    uint tile = texelFetch(u_wang_index, clamp(ivec2(floor(p)), ivec2(0), cells - 1), 0).r;
    return float(int(tile) * u_layers_per_tile + v_layer);
}

// lod/shell_sampling.h slab_path and opacity_along (Engel et al. 2006 §9.1).
float slab_path(vec3 view, vec3 slice_normal) {
    float across = abs(dot(normalize(view), slice_normal));
    float thickness = abs(slice_normal.y);
    return across * k_max_path > thickness ? thickness / across : k_max_path;
}
float opacity_along(float alpha, float path) {
    return 1.0 - pow(1.0 - min(alpha, 0.999), path);
}

void main() {
    if (any(lessThan(v_local_xz, u_area.xy)) || any(greaterThanEqual(v_local_xz, u_area.zw))) discard;
    // Nearer than the fade's start nothing shows: no fetch (the test below would discard it too).
    float fade = clamp((length(v_position) - u_fade.x) / max(u_fade.y - u_fade.x, 1e-3), 0.0, 1.0);
    if (fade <= 0.0) discard;
    vec2 cell_f = (v_local_xz - u_lattice.xy) * u_lattice.w;
    vec2 uv = cell_f - floor(cell_f);
    // Gradients of the continuous coordinate: the jump of uv at a tile border picks no mip.
    vec2 dx = dFdx(cell_f);
    vec2 dy = dFdy(cell_f);
    // Anisotropic filtering by hand (lod/shell_sampling.h footprint_taps): the footprint's long
    // axis cut into `taps` pieces, each fetched from its own Wang tile at a piece's mip.
    float lx = length(dx);
    float ly = length(dy);
    float ratio = max(lx, ly) / max(min(lx, ly), 1e-6);
    int taps = int(clamp(ceil(ratio), 1.0, float(k_max_taps)));
    vec2 step = (lx > ly ? dx : dy) / float(taps);
    vec2 gx = (lx > ly ? step : dx) * u_footprint_scale;
    vec2 gy = (lx > ly ? dy : step) * u_footprint_scale;
    vec2 first = cell_f + (0.5 - 0.5 * float(taps)) * step;
    vec2 last = cell_f + (0.5 * float(taps) - 0.5) * step;
    // Most footprints lie within one Wang tile: then one lookup of the index serves every fetch.
    bool one_tile = all(equal(floor(first), floor(last)));
    float first_layer = slice_layer(first);
    vec4 c = vec4(0.0);
    for (int i = 0; i < taps; ++i) {
        vec2 p = first + float(i) * step;
        c += textureGrad(u_shell_colour, vec3(p - floor(p), one_tile ? first_layer : slice_layer(p)), gx, gy);
    }
    c /= float(taps);
    float layer = one_tile ? first_layer : slice_layer(cell_f);
    vec3 base = u_premultiplied != 0 ? c.rgb / max(c.a, 1e-4) : c.rgb;
    // The slab crossed along the view, not from above (lod/shell_sampling.h): the slice's plane
    // is its triangle's, slanted by Eq. 2.
    c.a = opacity_along(c.a, slab_path(v_position, normalize(cross(dFdx(v_position), dFdy(v_position)))));
    if (c.a * fade < 0.5 / 255.0) discard;
#ifdef SH_TRANSFER
#ifdef SHELL_RELIT
    vec4 sums = textureGrad(u_lit_seen, vec3(uv, layer), dx, dy);
    vec3 sky_seen = sums.rgb;
    float sun_seen = sums.a;
    float sun_other = textureGrad(u_lit_other, vec3(uv, layer), dx, dy).r;
#else
    float seen[9];
    float other[9];
    for (int p = 0; p < 5; ++p) {
        vec4 page = textureGrad(u_shell_transfer[p], vec3(uv, layer), dx, dy);
        // Luft 2007's k_a on the sky's light (page 4's blue, straight; 1 for a plain model).
        if (p == 4) sh_ambient = page.b;
        decode_transfer_page(p, page, seen, other);
    }
    vec3 sky_seen = sh_transfer_sky(seen);
    float sun_seen = sh_transfer_sun(seen);
    float sun_other = sh_transfer_sun(other);
#endif
    // The shadow map at the slice itself (exit 0): the plants the shell stands for cast nothing
    // into it, so it holds only other objects' shadows, as a plant's lookup outside its sphere does.
    vec3 lit = shade_transfer(base, sky_seen, sun_seen, sun_other, v_position, 0.0, true);
#else
    // The bake's blur and the mips average many leaves' normals: lit as they come
    // (shading.glsl filtered_normal, Toksvig 2005). On the far fields of docs/measure_shells.py
    // FLIP fell from 0.060/0.068/0.071 to 0.057/0.063/0.063 at 5°/10°/20° (landscape's: 0.0267
    // to 0.0258), SSIM +0.001.
    vec4 seen_from_above = textureGrad(u_shell_normal, vec3(uv, layer), dx, dy);
    vec3 n = seen_from_above.rgb * 2.0 - 1.0;
#ifdef IMPLICIT_LIGHTING
    // Luft 2007 §3.2: the plants' normals carry k_a as their length, and the slices' are their
    // mean (setup/shell_assets.cpp): k_a decoded as the implicit-lit billboards and clouds decode
    // it, the direction then shortened by sin β as a plain slice's is (below): the slices show the
    // crowns' tops, the frame their sides. In tests/gl/shell_gl_test.cpp's shrubs seen from 25° the
    // shells' mean colour came 0.54x and 0.40x as far from the implicit-lit meshes' as the same
    // slices read as plain normals (sun at 60° and 15°); decoded but not shortened, 1.18x and 0.68x.
    float encoded_length = length(n);
    float ka = min(encoded_length, 1.0);
    n = encoded_length > 0.0 ? n / encoded_length : vec3(0.0, 1.0, 0.0);
#else
    n = filtered_normal(n);
#endif
    // Seen from β above the horizontal the leaves' seen sides agree less than from above: the
    // mean shortened by sin β (lod/shell_sampling.h seen_normal, where it is measured).
    n *= abs(normalize(v_position).y);
    // The sun through the slices above (alpha: their vertical transmittance T, lod/shell_canopy.h),
    // crossed over 1/sin e of each slab's thickness, so T^(1/sin e); only where the cascades hold
    // shadows, as the plants' rungs are shadowed by their neighbours only there. (On
    // docs/measure_shells.py's far fields, wholly beyond the cascades, the shade had lowered FLIP
    // while the slices' from-above normals lit them too bright; with the normal shortened
    // (seen_normal) it darkened them against their plants: without it there, 1 frame, SSIM
    // 0.9606/0.9480/0.9390 became 0.9615/0.9494/0.9401 at 5°/10°/20°, FLIP 0.0380/0.0378/0.0397
    // became 0.0371/0.0356/0.0361, the mean colour still within 1.5 of 255 of the reference's.)
    if (within_cascades(v_position)) sun_transmittance = pow(seen_from_above.a, 1.0 / max(u_sun_direction.y, 0.1));
#ifdef IMPLICIT_LIGHTING
    vec3 lit = shade_surface_ambient(base, n, v_position, true, ka);
#else
    vec3 lit = shade_surface(base, n, v_position, true);
#endif
#endif
    out_color = u_premultiplied != 0 ? vec4(lit * c.a, c.a) * fade : vec4(lit, c.a * fade);
    out_nearest = gl_FragCoord.z;
}
