#pragma once
// The offscreen framebuffer every frame is rendered into (RGBA8 colour, 24-bit depth, and for
// measurement an R32UI ID attachment: which draw-list instance covers each pixel). Headless
// capture reads it back; the window blits it to the default framebuffer.
#include <cstdint>
#include <vector>

#include "models/image/image.h"
#include "systems/render/gl_objects.h"

namespace sylva::render {

class render_target {
public:
    // `normal_buffer`: an RGBA8 attachment the view's surfaces write their normals to (the line
    // style's edge pass reads it with the depth).
    render_target(int width, int height, bool id_buffer = false, bool normal_buffer = false);
    void bind() const;
    // Which attachments the next draws write: colour only, or colour and IDs (when present).
    void draw_ids(bool enabled) const;
    // The opaque surfaces: colour, IDs and normals, those present.
    void draw_surfaces() const;
    bool has_normal_buffer() const { return m_normals.id() != 0; }
    GLuint normal_texture() const { return m_normals.id(); }
    GLuint depth_texture() const { return m_depth.id(); }
    image_rgba8 read_color() const;  // rows top to bottom
    // The ID attachment, rows top to bottom: 0 where nothing wrote an ID, else what the surface
    // shader wrote (draw-list instance index + 1). Empty without an ID buffer.
    std::vector<std::uint32_t> read_ids() const;
    // The same IDs in GL's row order (bottom row first) into `out`, reusing its storage: for
    // counting, where the order does not matter and a frame must not allocate. Empty without
    // an ID buffer.
    void read_ids_bottom_up(std::vector<std::uint32_t>& out) const;
    bool has_id_buffer() const { return m_ids.id() != 0; }
    void blit_to_default(int window_width, int window_height) const;
    int width() const { return m_width; }
    int height() const { return m_height; }

private:
    int m_width;
    int m_height;
    gl_texture m_color;
    gl_texture m_depth;
    gl_texture m_ids;
    gl_texture m_normals;
    gl_framebuffer m_framebuffer;
};

// Reads the window's back buffer (after a blit, before the overlay) as an image, top row first.
image_rgba8 read_default_framebuffer(int width, int height);

// Draws `image` (top row first) over the whole window's back buffer, scaled as blit_to_default
// scales a frame (the view's rung colours, app/rung_colours.h).
void draw_image_to_default(const image_rgba8& image, int window_width, int window_height);

}  // namespace sylva::render
