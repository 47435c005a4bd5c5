#pragma once
// A GL 4.5 core context and the surface it draws to. Two backends: OSMesa (headless, renders
// into memory; the default when there is no display or with --headless) and GLFW (a window).
// The thread that creates the context owns it: every GL call in Sylva happens on that thread.
#include <memory>
#include <string>

struct GLFWwindow;

namespace sylva::render {

struct context_options {
    int width = 960;
    int height = 540;
    bool headless = true;
    bool visible = true;  // GLFW only: false keeps the window hidden (tests)
    bool vsync = false;
    std::string title = "Sylva";
};

class gl_context {
public:
    virtual ~gl_context() = default;
    virtual void make_current() = 0;
    // Presents the default framebuffer (no-op headless).
    virtual void swap_buffers() = 0;
    // Polls window events; false once the user asked to close (always true headless).
    virtual bool poll_events() = 0;
    virtual GLFWwindow* window() { return nullptr; }
    virtual const char* backend_name() const = 0;

    int width() const { return m_width; }
    int height() const { return m_height; }
    // GL_RENDERER and GL_VERSION of the context, for metrics.
    const std::string& renderer() const { return m_renderer; }
    const std::string& version() const { return m_version; }

protected:
    void read_strings();  // fills m_renderer and m_version after the loader ran
    int m_width = 0;
    int m_height = 0;
    std::string m_renderer;
    std::string m_version;
};

// True when a display is reachable (DISPLAY or WAYLAND_DISPLAY set).
bool display_available();

// Creates a context with the backend the options ask for; throws std::runtime_error naming the
// backend and the reason when it cannot. Loads the GL entry points.
std::unique_ptr<gl_context> create_context(const context_options& options);
std::unique_ptr<gl_context> create_osmesa_context(const context_options& options);
std::unique_ptr<gl_context> create_glfw_context(const context_options& options);

}  // namespace sylva::render
