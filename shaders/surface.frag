// Shading of terrain, bark, leaves and baked billboards: sun light with cascaded shadows plus sky
// light from the environment's SH irradiance, leaves lit from behind by transmitted sunlight;
// then fog and tone mapping. MATERIAL_LEAF and MATERIAL_BILLBOARD alpha-test (also in the shadow
// pass, so they cast leaf-shaped shadows); billboards take their normal from a normal map baked
// from the plant (models/bake/crossed_billboard.h) and are shaded like leaves with it.
// WRITE_ID also writes which instance covers the pixel (measure/: coverage, lighting jumps).
// MATERIAL_BILLBOARD_CLOUD draws billboard-cloud quads (models/bake/billboard_cloud.h, Behrendt 2005
// §2.3): alpha-tested on the normal page's coverage, faded by the modified alpha test on the
// colour page's coverage x gaussian alpha (cloud_alpha_threshold), survivors opaque; lit with
// the normal page (normal-mapped) or, with CLOUD_PRE_LIT, with the billboard's own plane.
// FADE_DISSOLVE: the partner of a transition fades by a stable screen-door dissolve.
// SH_TRANSFER lights by precomputed radiance transfer (transfer.glsl, Behrendt 2005 §4): meshes
// and lines from the per-vertex dot products surface.vert made, billboard clouds and crossed
// billboards from the transfer pages of their atlases ("Gouraud-interpolated vectors in an
// extra texture").
// SPLAT_VISIBILITY (depth only, and the instance for the ID buffer) and SOFT_SPLATS (a Gaussian
// of peak opacity u_soft_alpha, blended) are the two passes of soft splats
// (lod/point_line_lod.h soft_splat_peak_alpha).
// PRIMITIVE_POINTS / PRIMITIVE_LINES shade the point and line representation (Deussen 2002):
// each sample takes the texture's colour where it was baked (a slightly filtered level: a
// splat stands for more surface than one texel), is never alpha-tested (the bake put it on an
// opaque texel), and is lit with its surface's normal turned towards the eye, as a leaf card's
// visible side is.
#include "common.glsl"

#ifdef LINE_QUADS
// Wide lines reach this shader through line.geom, whose outputs are g_*: the same varyings.
#define v_position g_position
#define v_normal g_normal
#define v_uv g_uv
#define v_tint g_tint
#define v_layer g_layer
#define v_instance g_instance
#define v_sh_sky g_sh_sky
#define v_sh_sun g_sh_sun
#define v_sh_exit g_sh_exit
#endif

in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in float v_tint;
flat in float v_layer;
#if defined(MATERIAL_BILLBOARD) || defined(MATERIAL_BILLBOARD_CLOUD)
flat in vec2 v_yaw_cos_sin;
// Model-space normals * 0.5 + 0.5; for clouds, alpha is the coverage.
layout(binding = 2) uniform sampler2DArray u_normal_map;
#endif
#if defined(FADE_DISSOLVE) || defined(MATERIAL_BILLBOARD_CLOUD)
flat in float v_fade;
#endif

#ifdef MATERIAL_BILLBOARD_CLOUD
// Behrendt 2005 §2.3: "a fragment is discarded, if its alpha value is below a threshold that is
// calculated by a simple piecewise linear function of the fragments distance to the viewer".
// The fade is piecewise-linear in distance (lod/billboard_cloud_lod.h); this maps it
// through three linear pieces from the least alpha a covered texel has (drawn whole) to above
// any alpha (gone). Mirrors cloud_alpha_threshold in lod/billboard_cloud_lod.cpp.
float cloud_alpha_threshold(float fade) {
    float f = clamp(fade, 0.0, 1.0);
    if (f >= 0.75) return mix(0.75, 0.18, (f - 0.75) / 0.25);
    if (f >= 0.5) return mix(0.90, 0.75, (f - 0.5) / 0.25);
    return mix(1.02, 0.90, f / 0.5);
}
#endif

#ifdef FADE_DISSOLVE
// A stable hash in [0, 1) (Jarzynski & Olano 2020's PCG-style mix, for a screen-door pattern
// that stays on the surface as the camera moves).
float dissolve_hash(uint a, uint b) {
    uint h = a * 747796405u + b * 2891336453u + 1u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    h = (h >> 22u) ^ h;
    return float(h >> 8u) * (1.0 / 16777216.0);
}
#endif
#if defined(SH_TRANSFER) && !defined(SHADOW_PASS)
#include "transfer.glsl"
#if defined(MATERIAL_BILLBOARD_CLOUD) || defined(MATERIAL_BILLBOARD)
#define TRANSFER_PAGES
// models/bake/transfer_pages.h: five layers per species, the 9 coefficients of the side this
// billboard side's viewer sees, then the 9 of the other, each (T / range) * 0.5 + 0.5.
layout(binding = 3) uniform sampler2DArray u_transfer_pages;
const float k_transfer_page_range = 1.25;  // mirrors models/bake/transfer_pages.h
flat in vec4 v_sh_sphere;
#else
in vec3 v_sh_sky;
in vec2 v_sh_sun;
in float v_sh_exit;
#if !defined(PRIMITIVE_SAMPLES)
in vec3 v_sh_sky_back;
#endif
#endif
#endif
#ifdef WRITE_ID
flat in uint v_instance;
layout(location = 1) out uint out_id;  // ID buffer: instance index + 1 (0 = nothing drawn)
#endif

layout(binding = 0) uniform sampler2DArray u_albedo;
#ifndef SHADOW_PASS
#include "shading.glsl"
layout(location = 0) out vec4 out_color;
#endif
#if defined(PRIMITIVE_POINTS) && !defined(SHADOW_PASS) && !defined(SPLAT_VISIBILITY)
flat in vec3 v_color;  // shaded per point in surface.vert
#endif
#ifdef SOFT_SPLATS
// The splat layer's nearest depth (systems/render/splat_layer.h), MIN-blended.
layout(location = 1) out float out_layer_depth;
uniform float u_soft_alpha;  // the Gaussian's peak opacity
flat in float v_opacity;     // the splat's own: less than 1 for a fractional prefix's last
#endif

#if defined(PRIMITIVE_POINTS) || defined(PRIMITIVE_LINES)
#define PRIMITIVE_SAMPLES
#endif

void main() {
#ifdef FADE_DISSOLVE
    // Whole triangles of a mesh, or texel-sized cells of a crossed billboard's quad, drop out in
    // an order fixed per plant (the tint is the plant's random number): no sorting, no blending.
#ifdef MATERIAL_BILLBOARD
    uint cell = uint(floor(v_uv.x * 512.0)) + 512u * uint(floor(v_uv.y * 256.0));
#else
    uint cell = uint(gl_PrimitiveID);
#endif
    if (dissolve_hash(cell, floatBitsToUint(v_tint)) >= v_fade) discard;
#endif
#ifdef SPLAT_VISIBILITY
#ifdef WRITE_ID
    out_id = v_instance + 1u;
#endif
    return;
#endif
#if defined(PRIMITIVE_POINTS) && !defined(SHADOW_PASS) && !defined(SPLAT_VISIBILITY)
#ifdef SOFT_SPLATS
    // exp(-2·|pc|²) over pc in [-1, 1]²: σ is a quarter of the splat's side; its mean over the
    // square is k_soft_splat_kernel_mean (lod/point_line_lod.h).
    vec2 pc = gl_PointCoord * 2.0 - 1.0;
    out_color = vec4(v_color, v_opacity * u_soft_alpha * exp(-2.0 * dot(pc, pc)));
    out_layer_depth = gl_FragCoord.z;
#else
    out_color = vec4(v_color, 1.0);
#ifdef WRITE_ID
    out_id = v_instance + 1u;
#endif
#endif
    return;
#endif
#if defined(MATERIAL_GROUND)
    vec4 albedo = texture(u_albedo, vec3(v_uv * u_params.w, v_layer));
#elif defined(PRIMITIVE_SAMPLES)
    vec4 albedo = textureLod(u_albedo, vec3(v_uv, v_layer), 1.0);
#else
    vec4 albedo = texture(u_albedo, vec3(v_uv, v_layer));
#endif
#if defined(MATERIAL_BILLBOARD_CLOUD)
    vec4 normal_texel = texture(u_normal_map, vec3(v_uv, v_layer));
    if (normal_texel.a < 0.5) discard;  // coverage, as the crossed billboard's test
#ifndef SHADOW_PASS
    if (albedo.a < cloud_alpha_threshold(v_fade)) discard;
#endif
#elif (defined(MATERIAL_LEAF) || defined(MATERIAL_BILLBOARD)) && !defined(PRIMITIVE_SAMPLES)
    if (albedo.a < 0.5) discard;
#endif
#ifndef SHADOW_PASS
    vec3 base = albedo.rgb * (1.0 + 0.18 * v_tint);
    vec3 n = normalize(v_normal);
#if defined(PRIMITIVE_SAMPLES)
    if (dot(n, v_position) > 0.0) n = -n;  // the side of the surface that faces the eye
#elif defined(MATERIAL_LEAF)
    if (!gl_FrontFacing) n = -n;  // leaves are thin double-sided cards
#endif
#ifdef MATERIAL_BILLBOARD
    // The baked normal faces the side the billboard was rendered from; seen from the other
    // side (which shows the mirror image), reflect it through the quad's plane.
    vec3 plane = n;
    vec3 m = texture(u_normal_map, vec3(v_uv, v_layer)).xyz * 2.0 - 1.0;
    float c = v_yaw_cos_sin.x, s = v_yaw_cos_sin.y;
    n = normalize(mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c) * m);
    if (dot(plane, -v_position) < 0.0) n -= 2.0 * dot(n, plane) * plane;
#endif
#if defined(MATERIAL_BILLBOARD_CLOUD) && !defined(CLOUD_PRE_LIT)
    // Normal-mapped (Behrendt 2005 §2.3): the bake stored each side's normals toward its own
    // viewer, and back faces are culled, so the rotated normal is the one seen.
    float c = v_yaw_cos_sin.x, s = v_yaw_cos_sin.y;
    n = normalize(mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c) * (normal_texel.xyz * 2.0 - 1.0));
#endif
#if defined(TRANSFER_PAGES) && defined(SH_TRANSFER)
    // The atlas holds model-space transfer; turn it by the plant's yaw, as surface.vert does
    // for vertices.
    float seen[9], other[9];
    float first_page = u_species[int(v_layer + 0.5)].z;
    for (int p = 0; p < 5; ++p) {
        vec4 t = (texture(u_transfer_pages, vec3(v_uv, first_page + float(p))) * 2.0 - 1.0) * k_transfer_page_range;
        for (int k = 0; k < 4; ++k) {
            int i = 4 * p + k;
            if (i < 9) seen[i] = t[k];
            else if (i < 18) other[i - 9] = t[k];
        }
    }
#ifdef MATERIAL_BILLBOARD
    // A crossed billboard seen from behind shows its front image mirrored through the quad's
    // plane, as the normal-mapped path reflects its normals: mirror the transfer too. The quads
    // are axis-aligned in model space (models/bake/crossed_billboard.h): the x-y quad (normal z)
    // flips the coefficients odd in z (2, 5, 7), the z-y quad (normal x) those odd in x (3, 4, 7).
    if (dot(plane, -v_position) < 0.0) {
        vec3 model_plane = vec3(v_yaw_cos_sin.x * plane.x - v_yaw_cos_sin.y * plane.z, plane.y,
                                v_yaw_cos_sin.y * plane.x + v_yaw_cos_sin.x * plane.z);
        bool xy_quad = abs(model_plane.z) > abs(model_plane.x);
        for (int i = 2; i < 8; ++i) {
            bool odd = xy_quad ? (i == 2 || i == 5 || i == 7) : (i == 3 || i == 4 || i == 7);
            if (odd) {
                seen[i] = -seen[i];
                other[i] = -other[i];
            }
        }
    }
#endif
    sh_rotate_about_y(seen, v_yaw_cos_sin.x, v_yaw_cos_sin.y);
    sh_rotate_about_y(other, v_yaw_cos_sin.x, v_yaw_cos_sin.y);
    out_color = vec4(shade_transfer(base, sh_transfer_sky(seen), sh_transfer_sun(seen), sh_transfer_sun(other),
                                    v_position, sphere_exit_distance(v_position, v_sh_sphere), true), 1.0);
#elif defined(SH_TRANSFER)
#if defined(PRIMITIVE_SAMPLES) && defined(MATERIAL_LEAF)
    out_color = vec4(shade_transfer(base, v_sh_sky, v_sh_sun.x, v_sh_sun.y, v_position, v_sh_exit, true), 1.0);
#elif defined(PRIMITIVE_SAMPLES)
    out_color = vec4(shade_transfer(base, v_sh_sky, v_sh_sun.x, v_sh_sun.y, v_position, v_sh_exit, false), 1.0);
#elif defined(MATERIAL_LEAF)
    // A leaf card seen from its back face is lit by its back transfer (as !gl_FrontFacing turns
    // the normal in the normal-lit path).
    if (gl_FrontFacing)
        out_color = vec4(shade_transfer(base, v_sh_sky, v_sh_sun.x, v_sh_sun.y, v_position, v_sh_exit, true), 1.0);
    else
        out_color = vec4(shade_transfer(base, v_sh_sky_back, v_sh_sun.y, v_sh_sun.x, v_position, v_sh_exit, true), 1.0);
#else
    // Bark is one-sided and back-face culled: always the side its normal faces.
    out_color = vec4(shade_transfer(base, v_sh_sky, v_sh_sun.x, v_sh_sun.y, v_position, v_sh_exit, false), 1.0);
#endif
#elif defined(MATERIAL_BILLBOARD_CLOUD) && defined(CLOUD_PRE_LIT)
    // Pre-lit (Behrendt 2005 §2.3): the colour page was lit at bake time by one light with the
    // plant's own shadows (models/bake/billboard_cloud.h light_factor); only the scene's light
    // level, fog and tone mapping are applied here.
    out_color = vec4(shade_pre_lit(base, v_position), 1.0);
#elif defined(MATERIAL_LEAF) || defined(MATERIAL_BILLBOARD) || defined(MATERIAL_BILLBOARD_CLOUD)
    out_color = vec4(shade_surface(base, n, v_position, true), 1.0);
#else
    out_color = vec4(shade_surface(base, n, v_position, false), 1.0);
#endif
#ifdef WRITE_ID
    out_id = v_instance + 1u;
#endif
#endif
}
