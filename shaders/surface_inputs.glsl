// What every shaded surface fragment receives from surface.vert (or line.geom): the
// camera-relative position, the normal, the texture coordinates and layer, the plant's tint,
// and for the ID buffer (measure/: coverage, lighting jumps; WRITE_ID) the instance.

in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in float v_tint;
flat in float v_layer;
#if defined(IMPLICIT_LIGHTING) && (defined(MATERIAL_BILLBOARD) || defined(MATERIAL_BILLBOARD_CLOUD))
in float v_population;  // the neighbours' factor on k_a (instance.glsl population_ambient)
#endif
#ifdef WRITE_ID
flat in uint v_instance;
layout(location = 1) out uint out_id;  // ID buffer: instance index + 1 (0 = nothing drawn)
#endif

layout(binding = 0) uniform sampler2DArray u_albedo;
layout(location = 0) out vec4 out_color;
#ifdef WRITE_NORMAL
// The normal buffer the line style's edge pass reads (shaders/edges.frag): the normal the surface
// was lit with, * 0.5 + 0.5, and 1 in alpha where a surface was drawn.
layout(location = 2) out vec4 out_normal;
#endif
