#include "systems/render/passes/pass_context.h"

namespace sylva::render {
namespace {

constexpr GLenum gl_mode(primitive_kind p) {
    return p == primitive_kind::triangles ? GL_TRIANGLES
                                          : (p == primitive_kind::lines ? GL_LINES : GL_POINTS);
}

}  // namespace

void pass_context::draw_group(const command_range& range, GLuint program, bool cull_back_faces,
                              primitive_kind primitive) {
    if (range.count == 0) return;
    glUseProgram(program);
    if (cull_back_faces)
        glEnable(GL_CULL_FACE);
    else
        glDisable(GL_CULL_FACE);
    glMultiDrawElementsIndirect(gl_mode(primitive), GL_UNSIGNED_INT,
                                reinterpret_cast<const void*>(range.offset), GLsizei(range.count),
                                0);
    ++draw_calls;
}

}  // namespace sylva::render
