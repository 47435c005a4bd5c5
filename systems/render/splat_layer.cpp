#include "systems/render/splat_layer.h"

#include <stdexcept>

namespace sylva::render {

namespace {

// Read texel by texel, never filtered, and never past the far edge.
void read_as_texels(GLuint texture) {
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace

splat_layer::splat_layer(int frame_width, int frame_height, bool id_buffer, bool normal_buffer)
    : m_width((frame_width + 1) / 2),
      m_height((frame_height + 1) / 2),
      m_color(make_texture(GL_TEXTURE_2D)),
      m_nearest(make_texture(GL_TEXTURE_2D)),
      m_depth(make_texture(GL_TEXTURE_2D)),
      m_framebuffer(make_framebuffer()) {
    glTextureStorage2D(m_color.id(), 1, GL_RGBA8, m_width, m_height);
    glTextureStorage2D(m_nearest.id(), 1, GL_R32F, m_width, m_height);
    glTextureStorage2D(m_depth.id(), 1, GL_DEPTH_COMPONENT24, m_width, m_height);
    // Colour is filtered up to the frame (the blur); depth and IDs are read texel by texel.
    glTextureParameteri(m_color.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(m_color.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLuint t : {m_color.id(), m_nearest.id()}) {
        glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    glTextureParameteri(m_nearest.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(m_nearest.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glNamedFramebufferTexture(m_framebuffer.id(), GL_COLOR_ATTACHMENT0, m_color.id(), 0);
    glNamedFramebufferTexture(m_framebuffer.id(), GL_COLOR_ATTACHMENT1, m_nearest.id(), 0);
    glNamedFramebufferTexture(m_framebuffer.id(), GL_DEPTH_ATTACHMENT, m_depth.id(), 0);
    if (id_buffer) {
        m_ids = make_texture(GL_TEXTURE_2D);
        glTextureStorage2D(m_ids.id(), 1, GL_R32UI, m_width, m_height);
        // An integer texture with GL's default linear filters is incomplete and reads as 0.
        read_as_texels(m_ids.id());
        glNamedFramebufferTexture(m_framebuffer.id(), GL_COLOR_ATTACHMENT2, m_ids.id(), 0);
    }
    if (normal_buffer) {
        m_normals = make_texture(GL_TEXTURE_2D);
        glTextureStorage2D(m_normals.id(), 1, GL_RGBA8, m_width, m_height);
        read_as_texels(m_normals.id());  // a normal is one splat's, not a blend of two
        glNamedFramebufferTexture(m_framebuffer.id(), GL_COLOR_ATTACHMENT3, m_normals.id(), 0);
    }
    draw_blend();
    if (glCheckNamedFramebufferStatus(m_framebuffer.id(), GL_FRAMEBUFFER) !=
        GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("splat_layer: framebuffer incomplete");
}

void splat_layer::begin() const {
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    glViewport(0, 0, m_width, m_height);
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float far[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    const GLuint no_id[4] = {0, 0, 0, 0};
    const float far_depth = 1.0f;
    // Clears go to the draw buffers: name all of them first.
    const GLenum all[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1,
                           GLenum(m_ids.id() ? GL_COLOR_ATTACHMENT2 : GL_NONE),
                           GLenum(m_normals.id() ? GL_COLOR_ATTACHMENT3 : GL_NONE)};
    glNamedFramebufferDrawBuffers(m_framebuffer.id(), 4, all);
    glClearNamedFramebufferfv(m_framebuffer.id(), GL_COLOR, 0, none);
    glClearNamedFramebufferfv(m_framebuffer.id(), GL_COLOR, 1, far);
    if (m_ids.id()) glClearNamedFramebufferuiv(m_framebuffer.id(), GL_COLOR, 2, no_id);
    if (m_normals.id()) glClearNamedFramebufferfv(m_framebuffer.id(), GL_COLOR, 3, none);
    glClearNamedFramebufferfv(m_framebuffer.id(), GL_DEPTH, 0, &far_depth);
}

void splat_layer::draw_visibility() const {
    const GLenum buffers[3] = {GL_NONE, GLenum(m_ids.id() ? GL_COLOR_ATTACHMENT2 : GL_NONE),
                               GLenum(m_normals.id() ? GL_COLOR_ATTACHMENT3 : GL_NONE)};
    glNamedFramebufferDrawBuffers(m_framebuffer.id(), 3, buffers);
}

void splat_layer::draw_blend() const {
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(m_framebuffer.id(), 2, buffers);
}

}  // namespace sylva::render
