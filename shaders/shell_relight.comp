// Behrendt 2005 §4 on the shells: the light-dependent sums of the slices' SH transfer, once per
// light. A slice texel is lit by "the scalar product of the coefficients" with the sky's
// radiance and the sun's basis (transfer.glsl), and the light is the same for every texel of
// every tile, so the passes/shell_pass.h shell pass runs this when the sky or the sun changes,
// not per fragment: per transfer texel and mip level, sky_seen = T_seen . L_sky (rgb), sun_seen
// = T_seen . Y(l), sun_other = T_other . Y(l) (the sky's times Luft 2007's k_a), unclamped (shade_transfer clamps, as it does for
// the plants). The sums are linear in T, so a mip level of them is the sums of the transfer's
// mip level. The shell fragment then reads two textures instead of five and does no dot
// products.
#include "common.glsl"
#include "transfer.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(binding = 5) uniform sampler2DArray u_shell_transfer[5];  // shell.frag's layout, one level
layout(binding = 0, rgba16f) uniform writeonly image2DArray u_lit_seen;  // rgb sky_seen, a sun_seen
layout(binding = 1, r16f) uniform writeonly image2DArray u_lit_other;    // r sun_other
uniform int u_level;

void main() {
    ivec3 p = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(p.xy, imageSize(u_lit_seen).xy))) return;
    float seen[9];
    float other[9];
    float ambient = 1.0;
    for (int page = 0; page < 5; ++page) {
        vec4 raw = texelFetch(u_shell_transfer[page], p, u_level);
        // Luft 2007's k_a (models/bake/shell_bake.h: page 4's blue, straight): the sky's light times it.
        if (page == 4) ambient = raw.b;
        decode_transfer_page(page, raw, seen, other);
    }
    // Half floats: within their range (a sky at the scenario format's brightest would pass 65504
    // and store infinity, which tone mapping turns into NaN; held there it still maps to white).
    const float k_half_max = 65000.0;
    imageStore(u_lit_seen, p, clamp(vec4(ambient * sh_transfer_sky(seen), sh_transfer_sun(seen)), -k_half_max, k_half_max));
    imageStore(u_lit_other, p, vec4(clamp(sh_transfer_sun(other), -k_half_max, k_half_max), 0.0, 0.0, 0.0));
}
