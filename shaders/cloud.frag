// Billboard-cloud quads in the view (models/bake/billboard_cloud.h, Behrendt 2005 §2.3):
// alpha-tested on the normal page's coverage, faded by the modified alpha test on the colour
// page's coverage x gaussian alpha (cloud_alpha_threshold), survivors opaque. Lit with the
// normal page (normal-mapped), with the page lit at bake time (CLOUD_PRE_LIT), or by the
// transfer pages (SH_TRANSFER, transfer_pages.glsl).
#include "common.glsl"
#include "shading.glsl"
#include "surface_inputs.glsl"

flat in vec2 v_yaw_cos_sin;
flat in float v_fade;
// Model-space normals * 0.5 + 0.5; alpha is the coverage.
layout(binding = 2) uniform sampler2DArray u_normal_map;
#ifdef SH_TRANSFER
#include "transfer.glsl"
#include "transfer_pages.glsl"
#endif

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

void main() {
    vec4 albedo = texture(u_albedo, vec3(v_uv, v_layer));
    vec4 normal_texel = texture(u_normal_map, vec3(v_uv, v_layer));
    if (normal_texel.a < 0.5) discard;  // coverage, as the crossed billboard's test
    if (albedo.a < cloud_alpha_threshold(v_fade)) discard;
    vec3 base = albedo.rgb * (1.0 + 0.18 * v_tint);
#if defined(SH_TRANSFER)
#ifdef IMPLICIT_LIGHTING
    sh_ambient = min(length(normal_texel.xyz * 2.0 - 1.0) * v_population, 1.0);
#endif
    float seen[9], other[9];
    read_transfer_pages(seen, other);
    out_color = vec4(shade_transfer_pages(base, seen, other), 1.0);
#elif defined(CLOUD_PRE_LIT)
    // Pre-lit (Behrendt 2005 §2.3): the colour page was lit at bake time by one light with the
    // plant's own shadows (models/bake/billboard_cloud.h light_factor); only the scene's light
    // level, fog and tone mapping are applied here.
    out_color = vec4(shade_pre_lit(base, v_position), 1.0);
#elif defined(IMPLICIT_LIGHTING)
    // Luft 2007: the normal page holds the realigned normals times k_a (billboard_bake.cpp).
    float c = v_yaw_cos_sin.x, s = v_yaw_cos_sin.y;
    vec3 m = mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c) * (normal_texel.xyz * 2.0 - 1.0);
    out_color = vec4(shade_implicit(base, m * v_population, v_position, true), 1.0);
#else
    // Normal-mapped (Behrendt 2005 §2.3): the bake stored each side's normals toward its own
    // viewer, and back faces are culled, so the rotated normal is the one seen.
    float c = v_yaw_cos_sin.x, s = v_yaw_cos_sin.y;
    // Lit as it comes (shading.glsl filtered_normal, Toksvig 2005): on forest the clouds' SSIM
    // rose from 0.695 to 0.723, FLIP fell from 0.085 to 0.079.
    vec3 n = filtered_normal(mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c) * (normal_texel.xyz * 2.0 - 1.0));
    out_color = vec4(shade_surface(base, n, v_position, true), 1.0);
#endif
#ifdef WRITE_NORMAL
    {
        float c = v_yaw_cos_sin.x, s = v_yaw_cos_sin.y;
        vec3 page = mat3(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c) * (normal_texel.xyz * 2.0 - 1.0);
        out_normal = vec4(normalize(page) * 0.5 + 0.5, 1.0);
    }
#endif
#ifdef WRITE_ID
    out_id = v_instance + 1u;
#endif
}
