#include "systems/render/gl_context.h"

#include <cstdlib>

#include "systems/render/gl.h"

namespace sylva::render {

void gl_context::read_strings() {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    m_renderer = renderer ? renderer : "unknown";
    m_version = version ? version : "unknown";
}

bool display_available() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

std::unique_ptr<gl_context> create_context(const context_options& options) {
    if (options.headless) return create_osmesa_context(options);
    return create_glfw_context(options);
}

}  // namespace sylva::render
