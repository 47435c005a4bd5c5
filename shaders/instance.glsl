// Every mesh Sylva draws (terrain, bark, leaves, billboards, point and line samples) is an
// instanced mesh: model vertices from the shared vertex buffer, one instance record
// (resources/draw_list.h instance_gpu: camera-relative position, yaw, scale, tint, fade, texture
// layer) per instance.

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_instance_position_yaw;
layout(location = 4) in vec4 in_instance_scale_tint_fade_layer;

// The vertex placed by its instance: turned by the yaw (c, s), scaled, moved.
struct instance_pose {
    float c;
    float s;
    mat3 rotation;
    float scale;
    vec3 world;  // camera-relative world position
};

instance_pose pose_instance() {
    instance_pose p;
    float yaw = in_instance_position_yaw.w;
    p.s = sin(yaw);
    p.c = cos(yaw);
    p.rotation = mat3(p.c, 0.0, -p.s, 0.0, 1.0, 0.0, p.s, 0.0, p.c);
    p.scale = in_instance_scale_tint_fade_layer.x;
    p.world = p.rotation * (in_position * p.scale) + in_instance_position_yaw.xyz;
    return p;
}
