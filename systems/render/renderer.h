#pragma once
// The GL submission of a frame: shadow cascades, opaque surfaces, the sky and soft splats
// (systems/render/passes/), each pass a few multi-draw-indirect calls over the shared mesh pool
// with per-instance data and indirect commands streamed through the persistent frame ring.
// Owned and called only by the thread that owns the GL context (the submit system is a
// main-thread system). Once warm, a frame allocates nothing and compiles nothing: programs are
// built with the meshes (program_table.h), commands go straight into the ring
// (draw_commands.h).
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "components/camera.h"
#include "components/environment.h"
#include "components/ground_tile.h"
#include "components/shell_tile.h"
#include "components/sun.h"
#include "lighting/shadow_cascades.h"
#include "lighting/sky_model.h"
#include "lod/point_line_lod.h"
#include "models/image/image.h"
#include "resources/draw_list.h"
#include "resources/frame_stats.h"
#include "resources/lodf_slots.h"
#include "resources/scene_assets.h"
#include "resources/shell_view.h"
#include "resources/terrain_shadow.h"
#include "systems/render/draw_commands.h"
#include "systems/render/frame_ring.h"
#include "systems/render/lodf_commands.h"
#include "systems/render/mesh_pool.h"
#include "systems/render/pass_timer.h"
#include "systems/render/passes/cloud_draw.h"
#include "systems/render/passes/edge_pass.h"
#include "systems/render/passes/lodf_draw.h"
#include "systems/render/passes/mesh_draw.h"
#include "systems/render/passes/pass_context.h"
#include "systems/render/passes/sample_draw.h"
#include "systems/render/passes/shell_pass.h"
#include "systems/render/passes/sky_pass.h"
#include "systems/render/passes/soft_splat_pass.h"
#include "systems/render/passes/surface_pass.h"
#include "systems/render/program_table.h"
#include "systems/render/render_target.h"
#include "systems/render/scene_textures.h"
#include "systems/render/shadow_maps.h"
#include "systems/render/sky_texture.h"
#include "systems/render/terrain_shadow_texture.h"

namespace sylva::render {

struct renderer_settings {
    int width = 960;
    int height = 540;
    int shadow_resolution = 1024;
    int cascades = 3;
    bool shadows = true;
    float exposure = 1.0f;
    // Measurement: also write which instance covers each pixel (read_ids). Costs one more
    // 32-bit write per shaded fragment, so only the bench asks for it.
    bool id_buffer = false;
    // Billboard-cloud transitions (Behrendt 2005 §2.3): surfaces other than clouds take the
    // screen-door dissolve by their instance's fade. Only scenes whose LOD policy fades ask for
    // it: a discard in the bark shader costs early depth rejection on a software rasteriser.
    bool fade_dissolve = false;
    // Luft 2007 §4: toon shading, the sun's and the sky's light quantised into bands.
    bool toon = false;
    // Luft 2007 §4 (Figure 7): a normal buffer beside the colour, and the edge pass's ink lines.
    bool lines = false;
};

// What one frame draws, gathered by the submit system from the ECS.
struct frame_view {
    const camera* view_camera = nullptr;
    const sun* sun_light = nullptr;
    const environment* sky = nullptr;
    const cascade_set* cascades = nullptr;
    const draw_list* draws = nullptr;
    glm::vec3 terrain_position{0.0f};  // camera-relative
    float time_s = 0.0f;
    // The point/line representation (Deussen 2002 §5): splat side in pixels and in image-plane
    // units at distance one, the sample distance d' on the image plane (shadow casters are
    // spaced by it, point_line_lod.h k_shadow_sample_spacing), and line width d' in pixels.
    float splat_px = 1.0f;
    float splat_plane = 0.0f;
    float sample_plane = 0.0f;
    float line_width_px = 1.0f;
    // Fog density by which splats grow with distance (point_line_lod.h fog_sample_distance; 0:
    // they do not), as the prefixes were counted.
    float sample_fog = 0.0f;
    // Soft splats (lod/point_line_lod.h): points are drawn after the sky, first as opaque
    // splats of splat_px into depth only (pushed back by k_soft_splat_depth_offset splats), then
    // as Gaussians of soft_splat_px with this peak opacity, blended over what is there.
    bool soft_splats = false;
    float soft_splat_px = 2.0f;
    float soft_splat_alpha = 1.0f;
    // Rebollo 2006: the plants on the LoDF rung (resources/lodf_slots.h), their slots' cluster
    // counters (the cluster_changes table, slot by slot) and the species' structures. Null
    // when no ladder reaches LoDF.
    const lodf_slots* lodf = nullptr;
    const cluster_changes* lodf_clusters = nullptr;
    const species_library* library = nullptr;
    // Behrendt 2005 §3: the shells' view and their tiles (in terrain tile order), when the scene
    // has shells; null otherwise.
    const shell_view* shells = nullptr;
    const shell_tile* shell_tiles = nullptr;
    std::size_t shell_tile_count = 0;
    // The ground tiles' grids this frame (components/ground_tile.h), in terrain tile order; none:
    // every tile on its finest grid.
    const ground_tile* ground_tiles = nullptr;
    std::size_t ground_tile_count = 0;
    // The terrain's shadow under this frame's sun (resources/terrain_shadow.h); null: the scene
    // has no terrain (or was built by hand), nothing is in a terrain's shadow.
    const terrain_shadow* terrain_shadows = nullptr;

    // Sets the point/line fields above from what the viewer asks; view_camera must be set.
    void set_samples(const point_line_quality& quality);
};

class renderer {
public:
    renderer(const renderer_settings& settings, const scene_assets& assets);
    ~renderer();
    renderer(const renderer&) = delete;
    renderer& operator=(const renderer&) = delete;

    // Records and submits the frame (returns once the GL commands are issued).
    void render(const frame_view& view);
    // Waits for the GPU and returns the frame's GPU timings and traffic (the caller adds its
    // own CPU timings: submit_cpu_ms, finish_ms).
    frame_stats finish();
    image_rgba8 read_color() const { return m_target.read_color(); }
    // The ID buffer of the last frame, rows top to bottom: 0 for no instance (sky, or no ID
    // buffer), else the index into the frame's draw_list::instances plus 1. The terrain is the
    // instance after the last plant instance.
    std::vector<std::uint32_t> read_ids() const { return m_target.read_ids(); }
    void read_ids_bottom_up(std::vector<std::uint32_t>& out) const { m_target.read_ids_bottom_up(out); }
    void present(int window_width, int window_height) const;
    std::size_t programs_compiled() const { return m_programs.compiled_count(); }
    std::uint64_t static_upload_bytes() const { return m_static_upload_bytes; }
    std::uint64_t shell_bytes() const { return m_shell_pass.uploaded_bytes(); }
    // How often the shells' SH transfer was summed with a light that held still (shell_pass).
    std::uint32_t shell_relights() const { return m_shell_pass.relights(); }
    // Uploads a mesh after construction (its id follows the scene's meshes) and builds the
    // programs it is drawn with; draw lists may then name it. Used by the primitive-cost
    // calibration.
    std::uint16_t add_mesh(const mesh_data& mesh);
    const renderer_settings& settings() const { return m_settings; }

private:
    void write_uniforms(const frame_view& view);
    void write_instances(const frame_view& view);
    // Rewrites the LoDF slots' commands whose clusters changed (systems/render/lodf_commands.h).
    void update_lodf(const frame_view& view);

    renderer_settings m_settings;
    mesh_pool m_meshes;
    program_table m_programs;
    frame_ring m_ring;
    render_target m_target;
    std::unique_ptr<shadow_maps> m_shadow_maps;
    pass_timer m_timer;
    scene_textures m_textures;
    sky_texture m_sky;
    terrain_shadow_texture m_terrain_shadow;
    draw_commands m_commands;
    float m_ground_uv_scale = 4.0f;
    std::uint32_t m_terrain_resolution = 0;  // the terrain's samples per side (0: none)
    double m_terrain_size_m = 0.0;
    // Rebollo 2006: the LoDF slots' indirect commands, when a species has LoDF foliage; the
    // species each slot's commands were written for (k_no_lodf_slot: none).
    std::uint32_t m_lodf_clusters = 0;  // the most LoDF clusters of any species; 0: no LoDF
    std::unique_ptr<lodf_commands> m_lodf;  // created by update_lodf for the world's slots
    std::vector<std::uint32_t> m_lodf_species;

    // The representations, in the order the surface passes draw them (passes/pass_context.h).
    mesh_draw m_mesh_draw;
    cloud_draw m_cloud_draw;
    sample_draw m_sample_draw;
    lodf_draw m_lodf_draw;
    std::array<const surface_draw*, 4> m_surface_draws{&m_mesh_draw, &m_cloud_draw, &m_sample_draw, &m_lodf_draw};
    // The frame's passes, in order.
    shadow_cascade_pass m_shadow_pass{m_surface_draws};
    opaque_pass m_opaque_pass{m_surface_draws};
    sky_pass m_sky_pass{m_sky};
    shell_pass m_shell_pass;
    soft_splat_pass m_soft_splat_pass{m_surface_draws};
    edge_pass m_edge_pass;
    std::array<frame_pass*, 6> m_passes{&m_shadow_pass, &m_opaque_pass,      &m_sky_pass,
                                        &m_shell_pass,  &m_soft_splat_pass, &m_edge_pass};
    pass_context m_context;

    std::size_t m_uniform_offset = 0;
    std::uint64_t m_frame_upload_bytes = 0;
    std::uint64_t m_lodf_bytes = 0;  // this frame's LoDF command uploads
    std::uint64_t m_static_upload_bytes = 0;
    double m_record_ms = 0.0;
};

}  // namespace sylva::render
