#pragma once
// The GL submission of a frame: shadow cascades, opaque surfaces (terrain, bark, alpha-tested
// leaves) and the sky, each pass a few multi-draw-indirect calls over the shared mesh pool with
// per-instance data streamed through the persistent frame ring. Owned and called only by the
// thread that owns the GL context (the submit system is a main-thread system).
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "components/camera.h"
#include "components/environment.h"
#include "components/sun.h"
#include "models/image/image.h"
#include "resources/draw_list.h"
#include "resources/frame_stats.h"
#include "lighting/shadow_cascades.h"
#include "lighting/sky_model.h"
#include "lod/point_line_lod.h"
#include "systems/render/frame_ring.h"
#include "systems/render/mesh_pool.h"
#include "systems/render/pass_timer.h"
#include "systems/render/render_target.h"
#include "systems/render/shader_library.h"
#include "systems/render/shadow_maps.h"
#include "systems/render/splat_layer.h"
#include "resources/scene_assets.h"

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
    void present(int window_width, int window_height) const;
    std::size_t programs_compiled() const { return m_shaders.compiled_count(); }
    std::uint64_t static_upload_bytes() const { return m_static_upload_bytes; }
    // Uploads a mesh after construction (its id follows the scene's meshes); draw lists may then
    // name it. Used by the primitive-cost calibration.
    std::uint16_t add_mesh(const mesh_data& mesh) { return m_meshes.add(mesh); }
    const renderer_settings& settings() const { return m_settings; }

private:
    struct command_range {
        std::size_t offset = 0;  // bytes into the ring buffer
        std::uint32_t count = 0;
    };
    // Indirect command groups per pass (shadow cascades and opaque), material, primitive and
    // lighting variant. material_kind: bark, leaf, ground, billboard, billboard_cloud
    static constexpr std::size_t k_materials = 5;
    static constexpr std::size_t k_primitives = 3;  // primitive_kind: triangles, points, lines
    static constexpr std::size_t k_groups_per_pass =
        k_materials * k_primitives * k_lighting_variants;
    using pass_commands = std::array<command_range, k_groups_per_pass>;
    // glMultiDrawElementsIndirect's command layout (GL 4.3 §10.4).
    struct indirect_command {
        std::uint32_t count;
        std::uint32_t instance_count;
        std::uint32_t first_index;
        std::int32_t base_vertex;
        std::uint32_t base_instance;
    };
    static constexpr std::size_t k_command_groups = std::size_t(render_pass::count) * k_groups_per_pass;
    static constexpr std::size_t group_of(material_kind m, primitive_kind p,
                                          lighting_variant l = lighting_variant::normal_mapped) {
        return (std::size_t(l) * k_primitives + std::size_t(p)) * k_materials + std::size_t(m);
    }

    void update_sky_texture(const frame_view& view);
    void upload_sky_grid();
    void write_uniforms(const frame_view& view);
    void write_instances(const frame_view& view);
    void write_commands(const frame_view& view);
    void draw_group(const command_range& range, GLuint program, bool cull_back_faces,
                    primitive_kind primitive = primitive_kind::triangles);
    // What draw_samples draws: points and lines into a shadow cascade; the view's opaque
    // samples (lines, and points unless they are soft); or the two passes of soft splats.
    enum class sample_pass { cascade, view, splat_visibility, soft_splats };
    // `pixel_scale`: splat sizes in the target drawn to over the frame's (the splat layer's
    // k_scale, or 1).
    void draw_samples(const pass_commands& groups, sample_pass pass, int cascade = -1,
                      float pixel_scale = 1.0f);
    void draw_soft_splats();
    void composite_splat_layer();
    void draw_clouds(const pass_commands& groups, int cascade);
    void write_species_block(const scene_assets& assets);
    static constexpr std::size_t k_max_species_spheres = 64;  // transfer.glsl u_species_sphere
    static constexpr std::array<lighting_variant, k_lighting_variants> k_all_lightings{
        lighting_variant::normal_mapped, lighting_variant::pre_lit, lighting_variant::sh};
    void draw_shadow_cascades();
    void draw_opaque();
    void draw_sky();
    GLuint surface_program(material_kind material, bool shadow,
                           primitive_kind primitive = primitive_kind::triangles,
                           lighting_variant lighting = lighting_variant::normal_mapped,
                           sample_pass samples = sample_pass::view);

    renderer_settings m_settings;
    shader_library m_shaders;
    mesh_pool m_meshes;
    frame_ring m_ring;
    render_target m_target;
    std::optional<splat_layer> m_splat_layer;  // made when soft splats are first drawn
    std::unique_ptr<shadow_maps> m_shadow_maps;
    pass_timer m_timer;
    gl_texture m_leaf_textures;
    gl_texture m_bark_textures;
    gl_texture m_ground_texture;
    gl_texture m_billboard_albedo;  // crossed billboards: colour with coverage alpha
    gl_texture m_billboard_normal;  // and model-space normals
    gl_texture m_billboard_transfer;  // SH transfer pages, k_transfer_pages layers per species
    gl_texture m_cloud_albedo;      // billboard clouds: colour with coverage x gaussian alpha
    gl_texture m_cloud_normal;      // and model-space normals with coverage alpha
    gl_texture m_cloud_pre_lit;     // colour lit at bake time (pre-lit species)
    gl_texture m_cloud_transfer;    // SH transfer pages, k_transfer_pages layers per species
    gl_buffer m_species_block;      // transfer.glsl species_block: each species' sphere
    gl_texture m_sky_texture;
    std::vector<float> m_sky_grid;  // CPU radiance grid, reused when the sun moves
    std::optional<sky_model> m_sky_drawn;  // what m_sky_texture holds
    // The scene's environment map at the sky texture's size, when it has one: the sky is then
    // this map turned about the vertical, not the analytic sky.
    std::vector<float> m_map_sky;
    std::optional<std::pair<float, float>> m_map_drawn;  // (turn_deg, sky_intensity) drawn
    struct terrain_tile {
        std::uint16_t mesh = 0;
        glm::vec3 center{0.0f};  // terrain-local
        float radius = 0.0f;
    };
    std::vector<terrain_tile> m_terrain_tiles;
    float m_ground_uv_scale = 4.0f;
    std::array<pass_commands, static_cast<int>(render_pass::count)> m_commands{};
    // Commands per (pass, material) before they are copied to the ring; kept to avoid
    // allocating in the frame loop.
    std::array<std::vector<indirect_command>, k_command_groups> m_command_groups;
    std::size_t m_uniform_offset = 0;
    std::array<bool, k_max_cascades> m_cascades_holding_receivers{true, true, true, true};
    float m_splat_px = 1.0f;
    float m_sample_plane = 0.0f;
    float m_sample_fog = 0.0f;
    float m_splat_plane = 0.0f;
    float m_line_width_px = 1.0f;
    bool m_soft_splats = false;
    float m_soft_splat_px = 2.0f;
    float m_soft_splat_alpha = 1.0f;
    int m_cascade_count = 0;
    std::uint64_t m_frame_upload_bytes = 0;
    std::uint64_t m_static_upload_bytes = 0;
    std::uint32_t m_draw_calls = 0;
    std::uint32_t m_indirect_commands = 0;
    double m_record_ms = 0.0;
};

}  // namespace sylva::render
