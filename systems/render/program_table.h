#pragma once
// Every GLSL program a scene can draw with, compiled once when the renderer is made (and when
// a mesh is added) and then looked up by enums: the frame loop does no string work and no
// compile. Only the variants the scene's meshes can be drawn with are built (DESIGN §2: shaders
// no entity uses are not built).
//
// Surface programs are indexed by four axes:
//
//   pass_kind (5) x material_kind (5) x surface_primitive (4) x lighting_variant (5)
//   slot = ((pass * 5 + material) * 4 + primitive) * 5 + lighting       (500 slots)
//
// Depth-only passes (shadow, splat_visibility) light nothing: their lighting axis folds to
// normal_mapped. Slots whose sources are equal share one GL program. The pass picks the entry
// files (shaders/: mesh, cloud, line, point, splat_visibility, surface_shadow), the defines the
// material, lighting and measurement variants. A mesh of points gets both splat styles' programs
// and a mesh of lines both line widths': the frame chooses them (lod_policy splats, d'). The few
// screen-filling programs (sky, the splat layer's composite) have their own enum.
#include <array>
#include <cstddef>
#include <cstdint>

#include "models/mesh.h"
#include "resources/scene_assets.h"
#include "systems/render/draw_commands.h"
#include "systems/render/gl.h"
#include "systems/render/mesh_pool.h"
#include "systems/render/shader_library.h"

namespace sylva::render {

// What a surface program draws into: a shadow cascade's depth, the view, or one of the soft
// splats' two passes (lod/point_line_lod.h: depth-only visibility, then the blended Gaussians).
// view_faded: the view's programs for the faded partner of a transition (a mesh or crossed
// billboard dissolving by the screen door, shaders/mesh.frag FADE_DISSOLVE); a plant drawn whole
// is drawn by `view`, which has no dissolve to pay for per fragment.
enum class pass_kind : std::uint8_t { shadow, view, splat_visibility, soft_splats, view_faded, count };
// primitive_kind, with lines split by how they are widened: GL's own lines, or d'-wide quads
// from line.geom (chosen per frame from d', so both are built).
enum class surface_primitive : std::uint8_t { triangles, points, lines, line_quads, count };
// splat_composite_visibility: the splat layer's visibility IDs and normals into the frame's
// ID and normal buffers (shaders/splat_layer.frag), built when the frame has either.
// shell: the shell slices over the terrain (passes/shell_pass.h), built when the scene has them,
// with shell_layer_depth and shell_composite, which fill the shell layer's depth and draw it over
// the frame (passes/shell_pass.h), and with an ID buffer shell_composite_ids, which
// writes the shells' ID where the layer covers a pixel. When the plants are SH-lit, `shell` sums the
// shells' SH transfer with the light per fragment, shell_relight (a compute program) sums it
// once for a light that holds still, and shell_relit draws with those sums.
enum class screen_program : std::uint8_t {
    sky,
    splat_composite,
    splat_composite_visibility,
    edges,
    shell,
    shell_layer_depth,
    shell_composite,
    shell_composite_ids,
    shell_relight,
    shell_relit,
    count
};

constexpr surface_primitive surface_primitive_of(primitive_kind p, bool line_quads = false) {
    if (p == primitive_kind::lines)
        return line_quads ? surface_primitive::line_quads : surface_primitive::lines;
    return p == primitive_kind::points ? surface_primitive::points : surface_primitive::triangles;
}

// A linked program and the locations of the per-draw uniforms the passes set (-1 where the
// program has none: glUniform* ignores -1, as it did when the location was asked every draw).
struct surface_program {
    GLuint id = 0;
    GLint cascade = -1;
    GLint splat_px = -1;
    GLint splat_plane = -1;
    GLint splat_texels = -1;
    GLint shadow_push = -1;
    GLint sample_fog = -1;
    GLint sample_growth_max = -1;
    GLint depth_push = -1;
    GLint visibility_stride = -1;
    GLint soft_alpha = -1;
    GLint line_width_px = -1;
    GLint viewport_px = -1;
};

struct program_options {
    bool shadows = true;
    bool id_buffer = false;      // renderer_settings::id_buffer
    bool fade_dissolve = false;  // renderer_settings::fade_dissolve
    bool toon = false;           // renderer_settings::toon
    bool normals = false;        // renderer_settings::lines: the view writes its normal buffer
    bool shells = false;         // the scene has shell textures (passes/shell_pass.h)
    bool shell_transfer = false;  // ... lit by the SH transfer baked into them (SH_TRANSFER)
    bool shell_implicit = false;  // ... by normals carrying Luft 2007's k_a (IMPLICIT_LIGHTING)
    // Some species is darkened by its neighbours (species.implicit.population): the implicit-lit
    // programs interpolate the instance's population factor (POPULATION_AMBIENT); without it every
    // factor is 1 and they skip it.
    bool population = false;
};

class program_table {
public:
    explicit program_table(const program_options& options);
    // Builds every program the mesh's submeshes can be drawn with that is not built yet.
    void prepare(const gpu_mesh& mesh);
    // The program for a draw; throws std::logic_error when it was never prepared (a mesh added
    // without prepare()), never compiles.
    const surface_program& surface(pass_kind pass, material_kind material, primitive_kind primitive,
                                   lighting_variant lighting, bool line_quads = false) const;
    GLuint screen(screen_program program) const;
    std::size_t compiled_count() const { return m_shaders.compiled_count(); }

    static constexpr std::size_t k_surface_slots =
        std::size_t(pass_kind::count) * k_material_kinds * std::size_t(surface_primitive::count) *
        k_lighting_variants;

private:
    static std::size_t slot_of(pass_kind pass, material_kind material, surface_primitive primitive,
                               lighting_variant lighting);
    void build(pass_kind pass, material_kind material, surface_primitive primitive,
               lighting_variant lighting);
    program_source source_of(pass_kind pass, material_kind material, surface_primitive primitive,
                             lighting_variant lighting) const;

    program_options m_options;
    shader_library m_shaders;  // compiles (and shares) programs; used at build time only
    std::array<surface_program, k_surface_slots> m_surface{};
    std::array<GLuint, std::size_t(screen_program::count)> m_screen{};
};

}  // namespace sylva::render
