#pragma once
// Behrendt 2005 §3: the far vegetation as shell textures over the terrain, drawn after the sky
// (it writes no depth, so the sky would cover it) with premultiplied blending, tile by terrain
// tile at the pyramid level its distance asks (lod/shell_levels.h), bottom slice first.
//
// On the GPU: the terrain's triangles once more with each triangle's centre per vertex (for the
// slanting, §3.2; static), the Wang tiles' slice pyramids as two 2-D array textures (colour and
// normal, layer = tile · layers_per_tile + first layer of the level + slice; with SH-lit plants,
// five of the SH transfer instead of the normal one, one per page, at a quarter of the texels a
// side (one array of all pages would pass GL's 2048 layers on `valley`), and two float arrays of
// their sums with the light), and the tiling as
// an index texture of tile types, one texel per lattice cell (§3.4). Mip levels are each layer's
// own: a tile's border texels were baked with the plants across it (models/bake/shell_bake.h),
// so neighbouring tiles' mips agree where their content does.
//
// By default the slices are blended into a half-resolution layer (systems/render/splat_layer.h,
// colour and nearest depth) that is then drawn over the frame; scenario shells.half_resolution
// false blends them straight into the frame.
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
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "components/shell_tile.h"
#include "lod/shell_levels.h"
#include "resources/scene_assets.h"
#include "systems/render/gl_objects.h"
#include "systems/render/passes/pass_context.h"
#include "systems/render/splat_layer.h"

namespace sylva::render {

class shell_pass final : public frame_pass {
public:
    // Nothing is made (and the pass draws nothing) when the scene has no shells.
    explicit shell_pass(const scene_assets& assets);
    void draw(pass_context& context) override;
    bool active() const { return m_slices > 0; }
    std::uint32_t levels() const { return std::uint32_t(m_level_first_layer.size()); }
    float slice_height_m() const { return m_slice_height; }
    std::uint64_t uploaded_bytes() const { return m_uploaded_bytes; }
    // How many times the SH transfer was summed with a new light (0 without transfer).
    std::uint32_t relights() const { return m_relights; }

private:
    // The program's uniforms, asked once (the frame does no string work).
    struct uniform_locations {
        GLuint program = 0;
        GLint terrain_position = -1, slice_height = -1, slant = -1, slant_reach = -1,
              premultiplied = -1, lattice = -1, area = -1, layers_per_tile = -1, fade = -1,
              level = -1, max_level = -1, level_criterion = -1, level_slices = -1,
              level_first_layer = -1, footprint_scale = -1;
    };
    static uniform_locations uniforms_of(GLuint program);
    // Binds the half-resolution layer (made or resized for the frame), cleared, with its depth
    // taken from the frame's.
    void begin_layer(pass_context& context);
    // True when m_lit_* hold the frame's light (summed now if the light held still since the
    // last frame); false when the light changed since the last frame: the shells then sum the
    // transfer per fragment.
    bool relight(pass_context& context);

    uniform_locations m_uniforms[2];  // the per-fragment program's, the relit one's
    std::uint32_t m_slices = 0;  // level 0's
    float m_slice_height = 0.0f;
    std::uint32_t m_layers_per_tile = 0;
    bool m_standard_blending = false;  // shell_textures::standard_blending
    std::vector<GLint> m_level_first_layer;  // by level, as the vertex shader's uniform arrays
    std::vector<GLint> m_level_slices;
    glm::vec4 m_lattice{0.0f};
    glm::vec4 m_area{0.0f};
    gl_texture m_colour;
    gl_texture m_normal;  // none when the slices are lit by transfer
    // Under SH transfer (shell_stack::transfer): one array per transfer page, the colour's layers,
    // and their sums with the light the shells were last lit by (shaders/shell_relight.comp):
    // rgb sky_seen and a sun_seen, r sun_other, half floats (held within their range by the
    // compute shader; 32-bit floats measured no faster to sample and take twice the memory).
    std::vector<gl_texture> m_transfer;
    gl_texture m_lit_seen;
    gl_texture m_lit_other;
    GLsizei m_transfer_texels = 0;
    GLsizei m_transfer_layers = 0;
    // The light m_lit_* hold: the sky's radiance SH (27) and the sun's direction (3); NaN until
    // the first frame, so the first frame always sums.
    std::array<float, 30> m_lit_for;
    std::array<float, 30> m_last_light;  // the previous frame's
    std::uint32_t m_relights = 0;
    GLint m_relight_level = -2;  // shell_relight's u_level, once asked
    gl_texture m_index;
    gl_buffer m_vertices;
    gl_vertex_array m_vertex_array;
    // By terrain tile, by grid (components/shell_tile.h): first vertex, count.
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> m_tile_ranges;
    std::uint64_t m_uploaded_bytes = 0;
    std::optional<splat_layer> m_layer;  // made when the shells are first drawn at half resolution
};

}  // namespace sylva::render
