#include "systems/render/passes/surface_pass.h"

#include <stdexcept>

#include "systems/render/renderer.h"

namespace sylva::render {

void shadow_cascade_pass::draw(pass_context& context) {
    if (context.cascade_count == 0) return;
    context.timer->begin(gpu_pass::shadow);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);
    for (int c = 0; c < context.cascade_count; ++c) {
        // No surface samples a cascade whose slice holds no receiver (fit_shadow_cascades).
        if (!context.view->cascades->holds_receivers[std::size_t(c)]) continue;
        context.shadows->bind_layer(c);
        for (const surface_draw* d : m_draws) d->draw(context, {pass_kind::shadow, c});
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    context.timer->end();
}

void opaque_pass::draw(pass_context& context) {
    context.timer->begin(gpu_pass::opaque);
    render_target& target = *context.target;
    target.bind();
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    if (target.has_id_buffer() || target.has_normal_buffer()) {
        target.draw_surfaces();
        const GLuint none = 0;
        if (target.has_id_buffer()) glClearBufferuiv(GL_COLOR, 1, &none);
        const GLfloat no_surface[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        if (target.has_normal_buffer()) glClearBufferfv(GL_COLOR, 2, no_surface);
    }
    if (context.shadows) glBindTextureUnit(1, context.shadows->texture());
    if (!context.textures->species_block.id()) throw std::logic_error("renderer: no species block");
    for (const surface_draw* d : m_draws) d->draw(context, {pass_kind::view});
    context.timer->end();
}

}  // namespace sylva::render
