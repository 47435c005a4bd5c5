#include "systems/render/passes/soft_splat_pass.h"

#include "lod/point_line_lod.h"
#include "systems/render/renderer.h"

namespace sylva::render {
namespace {

bool any_points(const pass_commands& groups) {
    for (const lighting_variant l : k_all_lightings)
        for (const material_kind m : {material_kind::bark, material_kind::leaf})
            if (groups[group_of(m, primitive_kind::points, l)].count > 0) return true;
    return false;
}

}  // namespace

void soft_splat_pass::draw(pass_context& context) {
    const frame_view& view = *context.view;
    if (!view.soft_splats || !any_points(context.commands->pass(render_pass::opaque))) return;
    context.timer->begin(gpu_pass::splats);
    render_target& target = *context.target;
    const bool layered = view.soft_splat_px >= k_splat_layer_min_side_px;
    // Splats keep their size in the frame: in layer pixels they are k_scale as wide.
    const float pixel_scale = layered ? splat_layer::k_scale : 1.0f;
    if (layered) {
        if (!m_layer)
            m_layer.emplace(context.settings->width, context.settings->height,
                            context.settings->id_buffer, target.has_normal_buffer());
        m_layer->begin();
        if (context.shadows)
            glBindTextureUnit(1, context.shadows->texture());  // the splats' lighting
    }
    glDepthMask(GL_TRUE);
    if (layered) {
        m_layer->draw_visibility();
    } else {
        // Depth, IDs and the line style's normals: what the blend pass does not write.
        glColorMaski(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        target.draw_surfaces();
    }
    for (const surface_draw* d : m_draws)
        d->draw(context, {pass_kind::splat_visibility, -1, pixel_scale});
    if (layered) {
        m_layer->draw_blend();
    } else {
        glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        target.draw_ids(false);
    }
    glDepthMask(GL_FALSE);
    glEnablei(GL_BLEND, 0);
    // Into the layer: premultiplied "over" with its coverage in alpha, and the nearest splat
    // depth beside it; into the frame: "over", the target's alpha kept.
    glBlendFuncSeparatei(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, layered ? GL_ONE : GL_ZERO,
                         layered ? GL_ONE_MINUS_SRC_ALPHA : GL_ONE);
    if (layered) {
        glEnablei(GL_BLEND, 1);
        glBlendEquationi(1, GL_MIN);
    }
    for (const surface_draw* d : m_draws)
        d->draw(context, {pass_kind::soft_splats, -1, pixel_scale});
    if (layered) glBlendEquationi(1, GL_FUNC_ADD);
    glDisable(GL_BLEND);
    if (layered) composite(context);
    glDepthMask(GL_TRUE);
    context.timer->end();
}

// Draws the splat layer over the frame (shaders/splat_layer.frag), then, when the frame has an
// ID or a normal buffer, the layer's visibility IDs and normals in a second pass that writes
// nothing else.
void soft_splat_pass::composite(pass_context& context) {
    render_target& target = *context.target;
    target.bind();
    glBindTextureUnit(0, m_layer->color());
    glBindTextureUnit(1, m_layer->nearest_depth());
    glEnablei(GL_BLEND, 0);
    glBlendFuncSeparatei(0, GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glUseProgram(context.programs->screen(screen_program::splat_composite));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++context.draw_calls;
    glDisable(GL_BLEND);
    if (m_layer->ids() != 0 || m_layer->normals() != 0) {
        if (m_layer->ids() != 0) glBindTextureUnit(2, m_layer->ids());
        if (m_layer->normals() != 0) glBindTextureUnit(3, m_layer->normals());
        target.draw_surfaces();
        glColorMaski(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glUseProgram(context.programs->screen(screen_program::splat_composite_visibility));
        glDrawArrays(GL_TRIANGLES, 0, 3);
        ++context.draw_calls;
        glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        target.draw_ids(false);
    }
}

}  // namespace sylva::render
