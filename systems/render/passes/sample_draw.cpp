#include "systems/render/passes/sample_draw.h"

#include "lod/point_line_lod.h"
#include "systems/render/renderer.h"

namespace sylva::render {

void sample_draw::draw(pass_context& context, const draw_target& target) const {
    const frame_view& view = *context.view;
    const pass_kind pass = target.kind;
    const bool shadow = pass == pass_kind::shadow;
    const bool soft = pass == pass_kind::splat_visibility || pass == pass_kind::soft_splats;
    // GL's own lines where d' is about a pixel, and in the shadow cascades (one texel wide).
    const bool line_quads = !shadow && view.line_width_px > k_native_line_width_px;
    const pass_commands& groups = target.commands(context);
    for (const lighting_variant lighting : k_all_lightings)
        for (const primitive_kind primitive : {primitive_kind::points, primitive_kind::lines}) {
            // Soft passes draw points only; the view's opaque samples leave soft points out.
            if (soft && primitive != primitive_kind::points) continue;
            if (pass == pass_kind::view && primitive == primitive_kind::points && view.soft_splats)
                continue;
            for (const material_kind material : {material_kind::bark, material_kind::leaf}) {
                const command_range& range = groups[group_of(material, primitive, lighting)];
                if (range.count == 0) continue;
                const surface_program& program =
                    context.programs->surface(pass, material, primitive, lighting, line_quads);
                glUseProgram(program.id);
                if (shadow) glUniform1i(program.cascade, target.cascade);
                if (pass == pass_kind::splat_visibility) {
                    glUniform1f(program.depth_push, k_soft_splat_depth_offset * view.splat_plane);
                    glUniform1i(program.visibility_stride, k_soft_splat_visibility_stride);
                }
                if (pass == pass_kind::soft_splats)
                    glUniform1f(program.soft_alpha, view.soft_splat_alpha);
                if (primitive == primitive_kind::points) {
                    glEnable(GL_PROGRAM_POINT_SIZE);
                    set_point_uniforms(context, target, program);
                } else if (line_quads) {
                    glUniform1f(program.line_width_px, view.line_width_px);
                    glUniform2f(program.viewport_px, float(context.settings->width),
                                float(context.settings->height));
                }
                glBindTextureUnit(0, material == material_kind::leaf ? context.textures->leaf.id()
                                                                     : context.textures->bark.id());
                context.draw_group(range, program.id, false, primitive);
            }
        }
}

void sample_draw::set_point_uniforms(const pass_context& context, const draw_target& target,
                                     const surface_program& program) {
    const frame_view& view = *context.view;
    const bool shadow = target.kind == pass_kind::shadow;
    glUniform1f(program.splat_px,
                target.pixel_scale *
                    (target.kind == pass_kind::soft_splats ? view.soft_splat_px : view.splat_px));
    // A cascade's splats are as wide as its samples are apart (c_p = 1,
    // compute_shadow_prefix): k_shadow_sample_texels texels, or k_shadow_sample_spacing times
    // the viewer's sample distance there.
    glUniform1f(program.splat_plane,
                shadow ? float(k_shadow_sample_spacing) * view.sample_plane : view.splat_plane);
    if (shadow) {
        glUniform1f(program.splat_texels, float(k_shadow_sample_texels));
        glUniform1f(program.shadow_push, float(k_shadow_splat_push));
    } else {
        glUniform1f(program.sample_fog, view.sample_fog);
        glUniform1f(program.sample_growth_max, float(k_fog_sample_growth_max));
    }
}

}  // namespace sylva::render
