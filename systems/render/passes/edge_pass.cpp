#include "systems/render/passes/edge_pass.h"

#include "systems/render/renderer.h"

namespace sylva::render {

void edge_pass::draw(pass_context& context) {
    render_target& target = *context.target;
    if (!target.has_normal_buffer()) return;
    context.timer->begin(gpu_pass::edges);
    target.bind();
    // Only the colour is written; the normals and depth are read (not attachments being drawn:
    // depth writes and test are off, the normal attachment is not a draw buffer).
    target.draw_ids(false);
    glDepthMask(GL_FALSE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnablei(GL_BLEND, 0);
    glBlendFuncSeparatei(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glUseProgram(context.programs->screen(screen_program::edges));
    glBindTextureUnit(0, target.normal_texture());
    glBindTextureUnit(1, target.depth_texture());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++context.draw_calls;
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    context.timer->end();
}

}  // namespace sylva::render
