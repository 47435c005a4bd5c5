// Shadow casters cut out of their texture: leaf cards (MATERIAL_LEAF) and crossed billboards
// (MATERIAL_BILLBOARD) by their colour's alpha, billboard clouds (MATERIAL_BILLBOARD_CLOUD) by
// their normal page's coverage, as in the view, so they cast leaf-shaped shadows. Clouds cast
// whole: the view's distance fade (cloud.frag) is the viewer's, not the sun's. Opaque casters
// and samples need no fragment shader at all.
in vec2 v_uv;
flat in float v_layer;
#ifdef MATERIAL_BILLBOARD_CLOUD
layout(binding = 2) uniform sampler2DArray u_normal_map;
#else
layout(binding = 0) uniform sampler2DArray u_albedo;
#endif

void main() {
#ifdef MATERIAL_BILLBOARD_CLOUD
    if (texture(u_normal_map, vec3(v_uv, v_layer)).a < 0.5) discard;
#else
    if (texture(u_albedo, vec3(v_uv, v_layer)).a < 0.5) discard;
#endif
}
