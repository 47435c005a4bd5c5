#pragma once
// The soft splats' own layer (lod/point_line_lod.h soft splats), at half the frame's
// resolution: the visibility pass and the Gaussians are drawn into it, and it is then drawn over
// the frame through bilinear filtering. The shell pass (passes/shell_pass.h) blends its slices
// into one of its own, without IDs or normals, the same way (its depth filled from the frame's).
//
// Why a layer. Composited over each other and cut per pixel by the visibility pass's depth
// test, soft splats leave hard pixel-sized edges that move as the camera does. Blurring the
// composited layer (a 3x3 tent, which drawing it at half size and filtering it back up is) takes
// them out: on landscape at d' = 3 popping fell from 3.563 to 3.461 and SSIM rose from 0.8721 to
// 0.8788, and a full-resolution layer through the same tent popped the same, so the blur and not
// the resolution does it, while wider Gaussians per splat popped more. At half size the
// Gaussians also cost a quarter of the fill (17 ms less rasteriser CPU per frame at d' = 3).
//
// Attachments: colour (premultiplied "over": the splats' colour times their coverage, and the
// coverage), the nearest splat's window depth (R32F, MIN-blended), a depth buffer for the
// visibility pass and, with the frame's ID buffer, the visibility splats' IDs, with its normal
// buffer (the line style) their normals. The composite (shaders/splat_layer.frag) writes the
// nearest depth of its 2x2 footprint as its own, so the frame's depth test hides what the
// terrain and other surfaces cover, pixel by pixel.
#include "lod/point_line_lod.h"
#include "systems/render/gl_objects.h"

namespace sylva::render {

// Soft splats of at least k_splat_layer_min_side_px (lod/point_line_lod.h) are drawn here.

class splat_layer {
public:
    // For a frame of frame_width x frame_height: (w + 1) / 2 x (h + 1) / 2.
    splat_layer(int frame_width, int frame_height, bool id_buffer, bool normal_buffer);
    // Binds the layer and clears it: no colour, coverage 0, depth and nearest depth 1, ID 0,
    // normal 0 (alpha 0: no splat).
    void begin() const;
    // The visibility pass writes depth and, with an ID buffer, IDs (fragment output 1), with a
    // normal buffer normals (output 2); the blend pass writes colour (output 0) and nearest
    // depth (output 1).
    void draw_visibility() const;
    void draw_blend() const;
    GLuint color() const { return m_color.id(); }
    GLuint nearest_depth() const { return m_nearest.id(); }
    GLuint ids() const { return m_ids.id(); }          // 0 without an ID buffer
    GLuint normals() const { return m_normals.id(); }  // 0 without a normal buffer
    int width() const { return m_width; }
    int height() const { return m_height; }
    // Window size of the layer relative to the frame's: every splat is drawn this many times
    // its frame size.
    static constexpr float k_scale = 0.5f;

private:
    int m_width;
    int m_height;
    gl_texture m_color;
    gl_texture m_nearest;
    gl_texture m_depth;
    gl_texture m_ids;
    gl_texture m_normals;
    gl_framebuffer m_framebuffer;
};

}  // namespace sylva::render
