#include "systems/render/program_table.h"

#include <stdexcept>
#include <string>

#include "models/bake/crossed_billboard.h"

namespace sylva::render {
namespace {

constexpr bool alpha_tested(material_kind m) {
    return m == material_kind::leaf || is_billboard(m) || m == material_kind::billboard_cloud;
}

// Points and lines are the samples of bark and leaf parts (Deussen 2002 §5): no other material
// is drawn as them.
constexpr bool drawn_as(material_kind m, primitive_kind p) {
    return p == primitive_kind::triangles || m == material_kind::bark || m == material_kind::leaf;
}

// The partners of a transition that fade by the screen-door dissolve: whole meshes and crossed
// billboards (a billboard cloud fades by its own threshold, points by their prefix; the terrain
// never fades).
constexpr bool dissolves(material_kind m, primitive_kind p) {
    return p == primitive_kind::triangles && m != material_kind::ground && m != material_kind::billboard_cloud;
}

// The shaders of a draw: one entry file per pass and representation (shaders/), so each reads
// as one path; the defines then choose only material, lighting and measurement variants.
const char* vertex_of(pass_kind pass, surface_primitive primitive) {
    if (pass == pass_kind::shadow) return "surface_shadow.vert";
    return primitive == surface_primitive::points ? "point.vert" : "surface.vert";
}

// Opaque shadow casters and splat visibility without an ID buffer are depth only: none.
// `visibility_outputs`: the splats' visibility pass writes IDs or normals, so it needs a
// fragment shader; without either it is depth only.
const char* fragment_of(pass_kind pass, material_kind material, surface_primitive primitive,
                        bool visibility_outputs) {
    switch (pass) {
        case pass_kind::shadow:
            return alpha_tested(material) && primitive == surface_primitive::triangles
                       ? "surface_shadow.frag"
                       : "";
        case pass_kind::splat_visibility:
            return visibility_outputs ? "splat_visibility.frag" : "";
        case pass_kind::soft_splats:
            return "point.frag";
        default:
            break;
    }
    if (primitive == surface_primitive::points) return "point.frag";
    if (primitive != surface_primitive::triangles) return "line.frag";
    return material == material_kind::billboard_cloud ? "cloud.frag" : "mesh.frag";
}

surface_program locate(GLuint id) {
    surface_program p;
    p.id = id;
    p.cascade = glGetUniformLocation(id, "u_cascade");
    p.splat_px = glGetUniformLocation(id, "u_splat_px");
    p.splat_plane = glGetUniformLocation(id, "u_splat_plane");
    p.splat_texels = glGetUniformLocation(id, "u_splat_texels");
    p.shadow_push = glGetUniformLocation(id, "u_shadow_push");
    p.sample_fog = glGetUniformLocation(id, "u_sample_fog");
    p.sample_growth_max = glGetUniformLocation(id, "u_sample_growth_max");
    p.depth_push = glGetUniformLocation(id, "u_depth_push");
    p.visibility_stride = glGetUniformLocation(id, "u_visibility_stride");
    p.soft_alpha = glGetUniformLocation(id, "u_soft_alpha");
    p.line_width_px = glGetUniformLocation(id, "u_line_width_px");
    p.viewport_px = glGetUniformLocation(id, "u_viewport_px");
    return p;
}

}  // namespace

program_table::program_table(const program_options& options) : m_options(options) {
    m_screen[std::size_t(screen_program::sky)] =
        m_shaders.program({"sky.vert", "sky.frag", {}, {}});
    if (options.normals)
        m_screen[std::size_t(screen_program::edges)] = m_shaders.program({"sky.vert", "edges.frag", {}, {}});
    if (options.shells) {
        std::vector<std::string> defines;
        if (options.toon) defines.push_back("STYLE_TOON");
        if (options.shell_transfer) defines.push_back("SH_TRANSFER");
        if (options.shell_implicit) defines.push_back("IMPLICIT_LIGHTING");
        m_screen[std::size_t(screen_program::shell)] = m_shaders.program({"shell.vert", "shell.frag", defines, {}});
        if (options.shell_transfer) {
            m_screen[std::size_t(screen_program::shell_relight)] =
                m_shaders.program({{}, {}, {}, {}, "shell_relight.comp"});
            defines.push_back("SHELL_RELIT");
            m_screen[std::size_t(screen_program::shell_relit)] = m_shaders.program({"shell.vert", "shell.frag", defines, {}});
        }
        m_screen[std::size_t(screen_program::shell_layer_depth)] =
            m_shaders.program({"sky.vert", "shell_layer_depth.frag", {}, {}});
        m_screen[std::size_t(screen_program::shell_composite)] =
            m_shaders.program({"sky.vert", "shell_composite.frag", {}, {}});
        if (options.id_buffer)
            m_screen[std::size_t(screen_program::shell_composite_ids)] =
                m_shaders.program({"sky.vert", "shell_composite.frag", {"WRITE_ID"}, {}});
    }
}

std::size_t program_table::slot_of(pass_kind pass, material_kind material,
                                   surface_primitive primitive, lighting_variant lighting) {
    // Depth-only passes light nothing: one program serves every lighting variant. The splats'
    // visibility pass also writes the line style's normals, which face the eye unless they are
    // Luft 2007's realigned ones (point.vert): those keep a program of their own.
    if (pass == pass_kind::shadow ||
        (pass == pass_kind::splat_visibility && !uses_implicit_normals(lighting)))
        lighting = lighting_variant::normal_mapped;
    if (pass == pass_kind::splat_visibility && uses_implicit_normals(lighting))
        lighting = lighting_variant::implicit;
    std::size_t slot = std::size_t(pass);
    slot = slot * k_material_kinds + std::size_t(material);
    slot = slot * std::size_t(surface_primitive::count) + std::size_t(primitive);
    return slot * k_lighting_variants + std::size_t(lighting);
}

void program_table::prepare(const gpu_mesh& mesh) {
    const primitive_kind p = mesh.primitive;
    for (const gpu_submesh& sub : mesh.submeshes) {
        const material_kind m = sub.material;
        const lighting_variant l = sub.lighting;
        if (!drawn_as(m, p)) continue;
        build(pass_kind::view, m, surface_primitive_of(p), l);
        if (dissolves(m, p) && m_options.fade_dissolve) build(pass_kind::view_faded, m, surface_primitive::triangles, l);
        if (m_options.shadows) build(pass_kind::shadow, m, surface_primitive_of(p), l);
        if (p == primitive_kind::lines) build(pass_kind::view, m, surface_primitive::line_quads, l);
        if (p == primitive_kind::points) {
            build(pass_kind::splat_visibility, m, surface_primitive::points, l);
            build(pass_kind::soft_splats, m, surface_primitive::points, l);
            auto& composite = m_screen[std::size_t(screen_program::splat_composite)];
            if (!composite) composite = m_shaders.program({"sky.vert", "splat_layer.frag", {}, {}});
            auto& visibility = m_screen[std::size_t(screen_program::splat_composite_visibility)];
            if ((m_options.id_buffer || m_options.normals) && !visibility) {
                std::vector<std::string> defines;
                if (m_options.id_buffer) defines.push_back("WRITE_ID");
                if (m_options.normals) defines.push_back("WRITE_NORMAL");
                visibility = m_shaders.program({"sky.vert", "splat_layer.frag", defines, {}});
            }
        }
    }
}

void program_table::build(pass_kind pass, material_kind material, surface_primitive primitive,
                          lighting_variant lighting) {
    surface_program& slot = m_surface[slot_of(pass, material, primitive, lighting)];
    if (slot.id) return;
    // The shader library shares one program between slots whose sources are the same.
    slot = locate(m_shaders.program(source_of(pass, material, primitive, lighting)));
}

const surface_program& program_table::surface(pass_kind pass, material_kind material,
                                              primitive_kind primitive, lighting_variant lighting,
                                              bool line_quads) const {
    const surface_program& p =
        m_surface[slot_of(pass, material, surface_primitive_of(primitive, line_quads), lighting)];
    if (!p.id) throw std::logic_error("program_table: a draw needs a program no mesh prepared");
    return p;
}

GLuint program_table::screen(screen_program program) const {
    const GLuint id = m_screen[std::size_t(program)];
    if (!id) throw std::logic_error("program_table: a screen program no mesh prepared");
    return id;
}

program_source program_table::source_of(pass_kind pass, material_kind material,
                                        surface_primitive primitive,
                                        lighting_variant lighting) const {
    const bool shadow = pass == pass_kind::shadow;
    const bool visibility_outputs = m_options.id_buffer || m_options.normals;
    program_source source{vertex_of(pass, primitive),
                          fragment_of(pass, material, primitive, visibility_outputs), {}, {}};
    if (primitive == surface_primitive::points) source.defines.push_back("PRIMITIVE_POINTS");
    if (pass == pass_kind::splat_visibility) {
        // Depth only (and the ID buffer's instance, which the blend pass does not write).
        source.defines.push_back("SPLAT_VISIBILITY");
        if (m_options.id_buffer) source.defines.push_back("WRITE_ID");
        if (m_options.normals) {
            // The line style's normal buffer (edges.frag) sees the splats, not what lies behind.
            source.defines.push_back("WRITE_NORMAL");
            if (uses_implicit_normals(lighting)) {
                source.defines.push_back("IMPLICIT_LIGHTING");
                if (m_options.population) source.defines.push_back("POPULATION_AMBIENT");
            }
        }
        return source;
    }
    if (pass == pass_kind::soft_splats) source.defines.push_back("SOFT_SPLATS");
    if (!shadow && m_options.toon) source.defines.push_back("STYLE_TOON");
    const bool view = pass == pass_kind::view || pass == pass_kind::view_faded;
    if (view && m_options.normals) source.defines.push_back("WRITE_NORMAL");
    if (primitive == surface_primitive::lines || primitive == surface_primitive::line_quads) {
        source.defines.push_back("PRIMITIVE_LINES");
        // d'-wide quads; GL's own one-pixel lines where d' is about a pixel, and in the shadow
        // cascades (one texel wide).
        if (primitive == surface_primitive::line_quads) {
            source.geometry = "line.geom";
            source.defines.push_back("LINE_QUADS");
        }
    }
    if (material == material_kind::leaf) source.defines.push_back("MATERIAL_LEAF");
    if (material == material_kind::ground) source.defines.push_back("MATERIAL_GROUND");
    if (is_billboard(material)) source.defines.push_back("MATERIAL_BILLBOARD");
    // Turned to the eye in the view only: in a shadow map it would turn with the eye too.
    // Its views' elevations and their place in the atlas, from the bake (models/bake/
    // crossed_billboard.h).
    if (material == material_kind::facing_billboard && !shadow) {
        source.defines.push_back("FACING_EYE");
        const auto& e = k_facing_elevations_deg;
        source.defines.push_back("FACING_ELEVATIONS radians(vec4(" + std::to_string(e[0]) + ", " + std::to_string(e[1]) +
                                 ", " + std::to_string(e[2]) + ", " + std::to_string(e[3]) + "))");
        source.defines.push_back("FACING_ELEVATION_S (1.0 / " + std::to_string(k_crossed_billboard_atlas_widths) + ".0)");
    }
    if (material == material_kind::billboard_cloud) {
        source.defines.push_back("MATERIAL_BILLBOARD_CLOUD");
        if (lighting == lighting_variant::pre_lit) source.defines.push_back("CLOUD_PRE_LIT");
    }
    if (uses_transfer(lighting) && material != material_kind::ground) source.defines.push_back("SH_TRANSFER");
    // Luft 2007: the normal's length (a billboard's normal page's too) is k_a.
    if (uses_implicit_normals(lighting) && material != material_kind::ground) {
        source.defines.push_back("IMPLICIT_LIGHTING");
        if (m_options.population) source.defines.push_back("POPULATION_AMBIENT");
    }
    // Partners of a transition are drawn in the view only, by their own programs (view_faded).
    if (pass == pass_kind::view_faded) source.defines.push_back("FADE_DISSOLVE");
    // The soft splats' blend pass writes the splat layer's nearest depth where IDs would go.
    if (!shadow && m_options.id_buffer && pass != pass_kind::soft_splats)
        source.defines.push_back("WRITE_ID");
    return source;
}

}  // namespace sylva::render
