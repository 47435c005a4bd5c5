// Whole meshes in the view: terrain (MATERIAL_GROUND), bark (no material define), alpha-tested
// leaf cards (MATERIAL_LEAF) and crossed billboards (MATERIAL_BILLBOARD). Sun light with
// cascaded shadows plus sky light from the environment's SH irradiance, leaves lit from behind
// by transmitted sunlight; then fog and tone mapping (shading.glsl). Billboards take their
// normal from a normal map baked from the plant (models/bake/crossed_billboard.h) and are
// shaded like leaves with it.
// SH_TRANSFER lights by precomputed radiance transfer (transfer.glsl, Behrendt 2005 §4): from
// the per-vertex dot products surface.vert made, billboards from the transfer pages of their
// atlas (transfer_pages.glsl).
// FADE_DISSOLVE: the partner of a transition fades by a stable screen-door dissolve.
#include "common.glsl"
#include "shading.glsl"
#include "surface_inputs.glsl"

#ifdef FADE_DISSOLVE
flat in float v_fade;
// A stable hash in [0, 1) (Jarzynski & Olano 2020's PCG-style mix, for a screen-door pattern
// that stays on the surface as the camera moves).
float dissolve_hash(uint a, uint b) {
    uint h = a * 747796405u + b * 2891336453u + 1u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    h = (h >> 22u) ^ h;
    return float(h >> 8u) * (1.0 / 16777216.0);
}
#endif
#ifdef MATERIAL_GROUND
// The terrain's normal where the fragment lies, from its own samples (systems/render/
// scene_textures.h ground_normal, x and z), read bilinearly as the finest grid's vertex normals
// would be interpolated: a coarser grid far away (components/ground_tile.h) keeps the terrain's
// shading and loses only its shape's sub-pixel detail. Without the texture (scenes built by
// hand), the vertex normal.
layout(binding = 11) uniform sampler2D u_ground_normal;
vec3 ground_normal(vec3 position, vec3 vertex_normal) {
    if (u_terrain_params.w < 0.5) return vertex_normal;
    vec2 uv = (position.xz + u_terrain_map.xy) * u_terrain_map.z + u_terrain_map.w;
    vec2 xz = texture(u_ground_normal, uv).rg;
    return normalize(vec3(xz.x, sqrt(max(1.0 - dot(xz, xz), 0.0)), xz.y));
}
#endif
#ifdef MATERIAL_BILLBOARD
flat in vec2 v_yaw_cos_sin;
// Model-space normals * 0.5 + 0.5.
layout(binding = 2) uniform sampler2DArray u_normal_map;
#endif
#ifdef SH_TRANSFER
#include "transfer.glsl"
#ifdef MATERIAL_BILLBOARD
#include "transfer_pages.glsl"
#else
// The side the normal faces, and v_sh_sky_back the other side's (surface.vert).
in vec3 v_sh_sky;
in vec2 v_sh_sun;
in float v_sh_exit;
in vec3 v_sh_sky_back;
#endif
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
#if defined(MATERIAL_GROUND)
    vec4 albedo = texture(u_albedo, vec3(v_uv * u_params.w, v_layer));
#else
    vec4 albedo = texture(u_albedo, vec3(v_uv, v_layer));
#endif
#if defined(MATERIAL_LEAF) || defined(MATERIAL_BILLBOARD)
    if (albedo.a < 0.5) discard;
#endif
    vec3 base = albedo.rgb * (1.0 + 0.18 * v_tint);
    vec3 n = normalize(v_normal);
#if defined(MATERIAL_GROUND)
    n = ground_normal(v_position, n);
#endif
#if defined(MATERIAL_LEAF)
    if (!gl_FrontFacing) n = -n;  // leaves are thin double-sided cards
#endif
#ifdef MATERIAL_BILLBOARD
    // The baked normal faces the side the billboard was rendered from; seen from the other
    // side (which shows the mirror image), reflect it through the quad's plane.
    vec3 plane = n;
    vec3 m = texture(u_normal_map, vec3(v_uv, v_layer)).xyz * 2.0 - 1.0;
#ifdef IMPLICIT_LIGHTING
    m *= v_population;
#endif
    float c = v_yaw_cos_sin.x, s = v_yaw_cos_sin.y;
    // The filtered normal is lit as it comes (shading.glsl filtered_normal, Toksvig 2005). On forest (3 frames at 480x270) the crossed
    // billboards' SSIM rose from 0.689 to 0.711 and FLIP fell from 0.104 to 0.097.
    n = mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c) * m;
#ifdef IMPLICIT_LIGHTING
    n = normalize(n);  // its length is Luft 2007's k_a, which scales the sky's light only
#else
    n = filtered_normal(n);
#endif
    if (dot(plane, -v_position) < 0.0) n -= 2.0 * dot(n, plane) * plane;
#endif
#if defined(SH_TRANSFER) && defined(IMPLICIT_LIGHTING) && defined(MATERIAL_BILLBOARD)
    sh_ambient = min(length(m), 1.0);
#elif defined(SH_TRANSFER) && defined(IMPLICIT_LIGHTING)
    sh_ambient = min(length(v_normal), 1.0);
#endif
#if defined(SH_TRANSFER) && defined(MATERIAL_BILLBOARD)
    float seen[9], other[9];
    read_transfer_pages(seen, other);
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
    out_color = vec4(shade_transfer_pages(base, seen, other), 1.0);
#elif defined(SH_TRANSFER) && defined(MATERIAL_LEAF)
    // A leaf card seen from its back face is lit by its back transfer (as !gl_FrontFacing turns
    // the normal in the normal-lit path).
    if (gl_FrontFacing)
        out_color = vec4(shade_transfer(base, v_sh_sky, v_sh_sun.x, v_sh_sun.y, v_position, v_sh_exit, true), 1.0);
    else
        out_color = vec4(shade_transfer(base, v_sh_sky_back, v_sh_sun.y, v_sh_sun.x, v_position, v_sh_exit, true), 1.0);
#elif defined(SH_TRANSFER)
    // Bark is one-sided and back-face culled: always the side its normal faces.
    out_color = vec4(shade_transfer(base, v_sh_sky, v_sh_sun.x, v_sh_sun.y, v_position, v_sh_exit, false), 1.0);
#elif defined(IMPLICIT_LIGHTING) && defined(MATERIAL_BILLBOARD)
    // The normal page's normals carry k_a as their length (models/bake/billboard_bake.cpp).
    out_color = vec4(shade_surface_ambient(base, n, v_position, true, min(length(m), 1.0)), 1.0);
#elif defined(IMPLICIT_LIGHTING) && defined(MATERIAL_LEAF)
    out_color = vec4(shade_implicit(base, v_normal, v_position, true), 1.0);
#elif defined(IMPLICIT_LIGHTING)
    out_color = vec4(shade_implicit(base, v_normal, v_position, false), 1.0);
#elif defined(MATERIAL_LEAF) || defined(MATERIAL_BILLBOARD)
    out_color = vec4(shade_surface(base, n, v_position, true), 1.0);
#else
    out_color = vec4(shade_surface(base, n, v_position, false), 1.0);
#endif
#ifdef WRITE_NORMAL
#if defined(IMPLICIT_LIGHTING) && !defined(MATERIAL_BILLBOARD)
    out_normal = vec4(normalize(v_normal) * 0.5 + 0.5, 1.0);  // realigned, not turned
#else
    out_normal = vec4(n / max(length(n), 1e-4) * 0.5 + 0.5, 1.0);  // unit, for the edges' test
#endif
#endif
#ifdef WRITE_ID
    out_id = v_instance + 1u;
#endif
}
