#pragma once
// Cascaded shadow maps: one depth texture array, a layer per cascade, each with its own
// framebuffer. Sampled with hardware depth comparison (sampler2DArrayShadow, linear = 2x2 PCF).
#include <vector>

#include "systems/render/gl_objects.h"

namespace sylva::render {

class shadow_maps {
public:
    shadow_maps(int resolution, int cascades);
    void bind_layer(int cascade) const;  // binds its framebuffer and viewport, clears depth
    GLuint texture() const { return m_depth.id(); }
    int resolution() const { return m_resolution; }
    int cascades() const { return m_cascades; }

private:
    int m_resolution;
    int m_cascades;
    gl_texture m_depth;
    std::vector<gl_framebuffer> m_framebuffers;
};

}  // namespace sylva::render
