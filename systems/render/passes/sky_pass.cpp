#include "systems/render/passes/sky_pass.h"

namespace sylva::render {

void sky_pass::draw(pass_context& context) {
    context.timer->begin(gpu_pass::sky);
    context.target->draw_ids(false);  // the sky leaves ID 0
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glUseProgram(context.programs->screen(screen_program::sky));
    glBindTextureUnit(0, m_sky.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++context.draw_calls;
    glDepthMask(GL_TRUE);
    context.timer->end();
}

}  // namespace sylva::render
