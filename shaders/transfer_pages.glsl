// SH transfer of crossed billboards and billboard clouds (Behrendt 2005 §4: "Gouraud-
// interpolated vectors in an extra texture"): models/bake/transfer_pages.h stores five layers
// per species, the 9 coefficients of the side this billboard side's viewer sees, then the 9 of
// the other, each (T / range) * 0.5 + 0.5. Needs common.glsl, transfer.glsl and shading.glsl
// first, and v_uv, v_layer, v_yaw_cos_sin, v_position declared.

layout(binding = 3) uniform sampler2DArray u_transfer_pages;
flat in vec4 v_sh_sphere;

// The model-space transfer of the texel, both sides.
void read_transfer_pages(out float seen[9], out float other[9]) {
    float first_page = u_species[int(v_layer + 0.5)].z;
    for (int p = 0; p < 5; ++p)
        decode_transfer_page(p, texture(u_transfer_pages, vec3(v_uv, first_page + float(p))), seen, other);
}

// The atlas holds model-space transfer; turn it by the plant's yaw, as surface.vert does for
// vertices, and light by it (foliage: the other side's sunlight shows through).
vec3 shade_transfer_pages(vec3 base, float seen[9], float other[9]) {
    sh_rotate_about_y(seen, v_yaw_cos_sin.x, v_yaw_cos_sin.y);
    sh_rotate_about_y(other, v_yaw_cos_sin.x, v_yaw_cos_sin.y);
    return shade_transfer(base, sh_transfer_sky(seen), sh_transfer_sun(seen), sh_transfer_sun(other),
                          v_position, sphere_exit_distance(v_position, v_sh_sphere), true);
}
