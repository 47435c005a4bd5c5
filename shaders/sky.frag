// The analytic sky (Preetham 1999, evaluated on the CPU into an equirectangular texture when
// the sun moves), or the scenario's environment map turned with the sun (the same texture,
// filled from the map), plus the sun's disk, with the same fog and tone mapping as the surfaces.
#include "common.glsl"
in vec2 v_ndc;
layout(binding = 0) uniform sampler2D u_sky;
out vec4 out_color;

void main() {
    vec4 far_point = u_inverse_view_projection * vec4(v_ndc, 1.0, 1.0);
    vec3 d = normalize(far_point.xyz / far_point.w);
    // Equirectangular lookup: u from the azimuth about +y, v from the elevation.
    float u = atan(d.x, -d.z) / 6.28318531 + 0.5;
    float v = acos(clamp(d.y, -1.0, 1.0)) / 3.14159265;
    vec3 sky = texture(u_sky, vec2(u, v)).rgb;
    float sun_cos = dot(d, u_sun_direction.xyz);
    // The sun's disk (0.53 degrees wide) with a soft edge.
    sky += u_sun_radiance.rgb * 40.0 * smoothstep(0.99996, 0.99999, sun_cos);
    float horizon = pow(1.0 - max(d.y, 0.0), 8.0);
    sky = mix(sky, u_fog.rgb, 0.6 * horizon);
    out_color = vec4(tone_map(sky), 1.0);
}
