#include "systems/render/shadow_maps.h"

#include <stdexcept>

namespace sylva::render {

shadow_maps::shadow_maps(int resolution, int cascades)
    : m_resolution(resolution), m_cascades(cascades), m_depth(make_texture(GL_TEXTURE_2D_ARRAY)) {
    glTextureStorage3D(m_depth.id(), 1, GL_DEPTH_COMPONENT24, resolution, resolution, cascades);
    glTextureParameteri(m_depth.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(m_depth.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(m_depth.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(m_depth.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(m_depth.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(m_depth.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    for (int c = 0; c < cascades; ++c) {
        gl_framebuffer fb = make_framebuffer();
        glNamedFramebufferTextureLayer(fb.id(), GL_DEPTH_ATTACHMENT, m_depth.id(), 0, c);
        glNamedFramebufferDrawBuffer(fb.id(), GL_NONE);
        glNamedFramebufferReadBuffer(fb.id(), GL_NONE);
        if (glCheckNamedFramebufferStatus(fb.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error("shadow_maps: cascade framebuffer incomplete");
        m_framebuffers.push_back(std::move(fb));
    }
}

void shadow_maps::bind_layer(int cascade) const {
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffers.at(std::size_t(cascade)).id());
    glViewport(0, 0, m_resolution, m_resolution);
    glClear(GL_DEPTH_BUFFER_BIT);
}

}  // namespace sylva::render
