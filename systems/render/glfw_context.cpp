// Windowed GL through GLFW (X11 or Wayland; under Xvfb in tests).
// glad's header must come first; GLFW_INCLUDE_NONE keeps GLFW from including the system gl.h.
#include "systems/render/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>
#include <string>

#include "systems/render/gl_context.h"

namespace sylva::render {
namespace {

std::string glfw_error() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown error";
}

class glfw_context final : public gl_context {
public:
    explicit glfw_context(const context_options& options) {
        if (!glfwInit()) throw std::runtime_error("GLFW: cannot initialise: " + glfw_error());
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
        m_window = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr,
                                    nullptr);
        if (!m_window) {
            std::string reason = glfw_error();
            glfwTerminate();
            throw std::runtime_error("GLFW: cannot open a GL 4.5 core window: " + reason);
        }
        make_current();
        glfwSwapInterval(options.vsync ? 1 : 0);
        if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)))
            throw std::runtime_error("GLFW: glad could not load the GL 4.5 entry points");
        glfwGetFramebufferSize(m_window, &m_width, &m_height);
        read_strings();
    }
    ~glfw_context() override {
        glfwDestroyWindow(m_window);
        glfwTerminate();
    }
    glfw_context(const glfw_context&) = delete;
    glfw_context& operator=(const glfw_context&) = delete;

    void make_current() override { glfwMakeContextCurrent(m_window); }
    void swap_buffers() override { glfwSwapBuffers(m_window); }
    bool poll_events() override {
        glfwPollEvents();
        return !glfwWindowShouldClose(m_window);
    }
    GLFWwindow* window() override { return m_window; }
    const char* backend_name() const override { return "glfw"; }

private:
    GLFWwindow* m_window = nullptr;
};

}  // namespace

std::unique_ptr<gl_context> create_glfw_context(const context_options& options) {
    return std::make_unique<glfw_context>(options);
}

}  // namespace sylva::render
