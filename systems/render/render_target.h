#pragma once
// The offscreen framebuffer every frame is rendered into (RGBA8 colour, 24-bit depth). Headless
// capture reads it back; the window blits it to the default framebuffer.
#include "models/image.h"
#include "systems/render/gl_objects.h"

namespace sylva::render {

class render_target {
public:
    render_target(int width, int height);
    void bind() const;
    image_rgba8 read_color() const;  // rows top to bottom
    void blit_to_default(int window_width, int window_height) const;
    int width() const { return m_width; }
    int height() const { return m_height; }

private:
    int m_width;
    int m_height;
    gl_texture m_color;
    gl_texture m_depth;
    gl_framebuffer m_framebuffer;
};

// Reads the window's back buffer (after a blit, before the overlay) as an image, top row first.
image_rgba8 read_default_framebuffer(int width, int height);

}  // namespace sylva::render
