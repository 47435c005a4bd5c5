#include "systems/render/gl_object_census.h"

#include "systems/render/gl.h"

namespace sylva::render {
namespace {

template <class Is>
std::size_t count_names(Is is_name) {
    std::size_t live = 0;
    unsigned unused_in_a_row = 0;
    for (GLuint name = 1; unused_in_a_row < k_census_gap; ++name) {
        if (is_name(name) == GL_TRUE) {
            ++live;
            unused_in_a_row = 0;
        } else {
            ++unused_in_a_row;
        }
    }
    return live;
}

}  // namespace

std::string gl_object_census::describe() const {
    return "buffers " + std::to_string(buffers) + ", textures " + std::to_string(textures) +
           ", vertex arrays " + std::to_string(vertex_arrays) + ", framebuffers " +
           std::to_string(framebuffers) + ", renderbuffers " + std::to_string(renderbuffers) +
           ", programs " + std::to_string(programs) + ", shaders " + std::to_string(shaders) +
           ", queries " + std::to_string(queries) + ", samplers " + std::to_string(samplers);
}

gl_object_census take_gl_object_census() {
    gl_object_census c;
    c.buffers = count_names([](GLuint n) { return glIsBuffer(n); });
    c.textures = count_names([](GLuint n) { return glIsTexture(n); });
    c.vertex_arrays = count_names([](GLuint n) { return glIsVertexArray(n); });
    c.framebuffers = count_names([](GLuint n) { return glIsFramebuffer(n); });
    c.renderbuffers = count_names([](GLuint n) { return glIsRenderbuffer(n); });
    c.programs = count_names([](GLuint n) { return glIsProgram(n); });
    c.shaders = count_names([](GLuint n) { return glIsShader(n); });
    c.queries = count_names([](GLuint n) { return glIsQuery(n); });
    c.samplers = count_names([](GLuint n) { return glIsSampler(n); });
    return c;
}

}  // namespace sylva::render
