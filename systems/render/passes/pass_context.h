#pragma once
// What every pass of a frame draws with, and the two small interfaces the frame is made of:
//
//   frame_pass    one step of the frame in its order: shadow cascades, opaque, sky, soft splats.
//   surface_draw  one representation's draws (meshes, billboard clouds, point and line samples),
//                 called by the passes that draw surfaces, once per target: each cascade, the
//                 view, the soft splats' two passes. A new representation is a new surface_draw
//                 in the renderer's list; the passes do not change.
//
// The renderer fills one pass_context per frame (no allocation) and hands it to each pass.
#include <array>
#include <cstdint>

#include "models/mesh.h"
#include "resources/sort_key.h"
#include "systems/render/draw_commands.h"
#include "systems/render/gl.h"
#include "systems/render/pass_timer.h"
#include "systems/render/program_table.h"
#include "systems/render/render_target.h"
#include "systems/render/scene_textures.h"
#include "systems/render/shadow_maps.h"

namespace sylva::render {

struct frame_view;
struct renderer_settings;

struct pass_context {
    const frame_view* view = nullptr;
    const renderer_settings* settings = nullptr;
    const program_table* programs = nullptr;
    const scene_textures* textures = nullptr;
    const draw_commands* commands = nullptr;
    render_target* target = nullptr;
    const shadow_maps* shadows = nullptr;  // null when the renderer draws no shadows
    pass_timer* timer = nullptr;
    int cascade_count = 0;         // cascades drawn this frame
    GLuint frame_indirect_buffer = 0;  // the ring the frame's commands are in: a draw that binds
                                       // another indirect buffer binds this one back
    std::uint32_t draw_calls = 0;  // counted by draw_group and the screen passes

    // One glMultiDrawElementsIndirect over a command group (nothing when it is empty).
    void draw_group(const command_range& range, GLuint program, bool cull_back_faces,
                    primitive_kind primitive = primitive_kind::triangles);
};

// Every lighting variant, in the order the passes draw their groups.
inline constexpr std::array<lighting_variant, k_lighting_variants> k_all_lightings{
    lighting_variant::normal_mapped, lighting_variant::pre_lit, lighting_variant::sh, lighting_variant::implicit,
    lighting_variant::sh_implicit};

// Where a surface_draw draws this time.
struct draw_target {
    pass_kind kind = pass_kind::view;
    int cascade = -1;          // pass_kind::shadow: which cascade
    float pixel_scale = 1.0f;  // splat sizes in the target over the frame's (splat_layer::k_scale)

    // The command groups of this target's pass: its cascade's, or the view's.
    const pass_commands& commands(const pass_context& context) const {
        return context.commands->pass(kind == pass_kind::shadow ? shadow_pass(cascade)
                                                                : render_pass::opaque);
    }
};

class surface_draw {
public:
    virtual ~surface_draw() = default;
    // Draws this representation's groups into `target`; kinds it has nothing for draw nothing.
    virtual void draw(pass_context& context, const draw_target& target) const = 0;
};

class frame_pass {
public:
    virtual ~frame_pass() = default;
    virtual void draw(pass_context& context) = 0;
};

}  // namespace sylva::render
