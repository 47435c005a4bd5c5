#pragma once
// Move-only owners of GL object names (GL 4.5 direct state access: glCreate*). Each wrapper
// deletes its object with the matching glDelete* call on the owning thread.
#include <utility>

#include "systems/render/gl.h"

namespace sylva::render {

template <void (*Delete)(GLuint)>
class gl_name {
public:
    gl_name() = default;
    explicit gl_name(GLuint id) : m_id(id) {}
    ~gl_name() { reset(); }
    gl_name(gl_name&& other) noexcept : m_id(std::exchange(other.m_id, 0)) {}
    gl_name& operator=(gl_name&& other) noexcept {
        if (this != &other) {
            reset();
            m_id = std::exchange(other.m_id, 0);
        }
        return *this;
    }
    gl_name(const gl_name&) = delete;
    gl_name& operator=(const gl_name&) = delete;

    GLuint id() const { return m_id; }
    explicit operator bool() const { return m_id != 0; }
    void reset() {
        if (m_id) Delete(m_id);
        m_id = 0;
    }

private:
    GLuint m_id = 0;
};

namespace detail {
inline void delete_buffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void delete_vertex_array(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void delete_texture(GLuint id) { glDeleteTextures(1, &id); }
inline void delete_framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void delete_program(GLuint id) { glDeleteProgram(id); }
inline void delete_query(GLuint id) { glDeleteQueries(1, &id); }
inline void delete_sampler(GLuint id) { glDeleteSamplers(1, &id); }
}  // namespace detail

using gl_buffer = gl_name<detail::delete_buffer>;
using gl_vertex_array = gl_name<detail::delete_vertex_array>;
using gl_texture = gl_name<detail::delete_texture>;
using gl_framebuffer = gl_name<detail::delete_framebuffer>;
using gl_program = gl_name<detail::delete_program>;
using gl_query = gl_name<detail::delete_query>;
using gl_sampler = gl_name<detail::delete_sampler>;

inline gl_buffer make_buffer() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    return gl_buffer(id);
}
inline gl_texture make_texture(GLenum target) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    return gl_texture(id);
}
inline gl_framebuffer make_framebuffer() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return gl_framebuffer(id);
}
inline gl_vertex_array make_vertex_array() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return gl_vertex_array(id);
}
inline gl_query make_query(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    return gl_query(id);
}

}  // namespace sylva::render
