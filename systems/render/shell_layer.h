#pragma once
// The shells' own layer (passes/shell_pass.h), at half the frame's resolution: the slices are
// blended into it and it is then drawn over the frame through bilinear filtering.
//
// Why a layer. A shell pixel is many slices deep (every slice of its level, and more where the
// slanted triangles of Behrendt 2005 Eq. 2 stand up toward a grazing view), each a lit fragment,
// so on a rasteriser without fill to spare (llvmpipe) the shells cost their covered pixels times
// their depth: 23 M fragments and over a second at 480x270 on `valley`. The far field they draw
// holds no detail a half-resolution layer loses (beyond the fade band a texel of the tiles is
// under a pixel and the fog washes it), and at half size the slices cost a quarter of the fill.
// (The same reasoning as "off-screen particles", Cantlay 2007, GPU Gems 3 ch. 23.)
//
// Depth, both ways. Before the slices, the layer's depth buffer takes the farthest of each 2x2
// of the frame's depths (shaders/shell_layer_depth.frag): a slice behind the terrain or a plant
// in all four pixels is hidden there, and one behind only some of them is kept. The slices write
// their nearest window depth (R32F, MIN-blended), and the composite (shaders/shell_composite.frag)
// is drawn at the nearest of the 2x2 texels its filter reads, so the frame's depth test cuts the
// layer pixel by pixel where a plant or the ground lies in front.
#include "systems/render/gl_objects.h"

namespace sylva::render {

class shell_layer {
public:
    // For a frame of frame_width x frame_height: (w + 1) / 2 x (h + 1) / 2.
    shell_layer(int frame_width, int frame_height);
    // Binds the layer and clears it: no colour, coverage 0, nearest depth 1. Its depth buffer
    // is then written by the depth pass (depth test always), and the slices test against it.
    void begin() const;
    GLuint color() const { return m_color.id(); }
    GLuint nearest_depth() const { return m_nearest.id(); }
    int width() const { return m_width; }
    int height() const { return m_height; }

private:
    int m_width;
    int m_height;
    gl_texture m_color;
    gl_texture m_nearest;
    gl_texture m_depth;
    gl_framebuffer m_framebuffer;
};

}  // namespace sylva::render
