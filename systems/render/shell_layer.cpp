#include "systems/render/shell_layer.h"

#include <stdexcept>

namespace sylva::render {

shell_layer::shell_layer(int frame_width, int frame_height)
    : m_width((frame_width + 1) / 2),
      m_height((frame_height + 1) / 2),
      m_color(make_texture(GL_TEXTURE_2D)),
      m_nearest(make_texture(GL_TEXTURE_2D)),
      m_depth(make_texture(GL_TEXTURE_2D)),
      m_framebuffer(make_framebuffer()) {
    glTextureStorage2D(m_color.id(), 1, GL_RGBA8, m_width, m_height);
    glTextureStorage2D(m_nearest.id(), 1, GL_R32F, m_width, m_height);
    glTextureStorage2D(m_depth.id(), 1, GL_DEPTH_COMPONENT24, m_width, m_height);
    // Colour is filtered up to the frame; the nearest depth is read texel by texel.
    glTextureParameteri(m_color.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(m_color.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(m_nearest.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(m_nearest.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    for (GLuint t : {m_color.id(), m_nearest.id()}) {
        glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    glNamedFramebufferTexture(m_framebuffer.id(), GL_COLOR_ATTACHMENT0, m_color.id(), 0);
    glNamedFramebufferTexture(m_framebuffer.id(), GL_COLOR_ATTACHMENT1, m_nearest.id(), 0);
    glNamedFramebufferTexture(m_framebuffer.id(), GL_DEPTH_ATTACHMENT, m_depth.id(), 0);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(m_framebuffer.id(), 2, buffers);
    if (glCheckNamedFramebufferStatus(m_framebuffer.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("shell_layer: framebuffer incomplete");
}

void shell_layer::begin() const {
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    glViewport(0, 0, m_width, m_height);
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float far[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glClearNamedFramebufferfv(m_framebuffer.id(), GL_COLOR, 0, none);
    glClearNamedFramebufferfv(m_framebuffer.id(), GL_COLOR, 1, far);
}

}  // namespace sylva::render
