#include "systems/render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_inverse.hpp>
#include <numbers>
#include <stdexcept>

#include "lighting/fog.h"
#include "lod/point_line_lod.h"
#include "systems/project_environment_system.h"
#include "systems/render/frame_uniforms.h"

namespace sylva::render {
namespace {

constexpr GLuint k_instance_binding = 1;

void setup_instance_attributes(GLuint vao) {
    // instance_gpu (resources/draw_list.h): two vec4 attributes and the population's packed
    // ambient (a uvec2), advanced once per instance.
    glVertexArrayAttribFormat(vao, 3, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribFormat(vao, 4, 4, GL_FLOAT, GL_FALSE, 16);
    glVertexArrayAttribIFormat(vao, 10, 2, GL_UNSIGNED_INT, 32);  // 5..9: vertex transfer
    for (GLuint a : {3u, 4u, 10u}) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribBinding(vao, a, k_instance_binding);
    }
    glVertexArrayBindingDivisor(vao, k_instance_binding, 1);
}

std::vector<terrain_tile> terrain_tiles_of(const scene_assets& assets) {
    std::vector<terrain_tile> tiles;
    const std::size_t count = assets.terrain_meshes.size();
    const auto side = std::int32_t(std::lround(std::sqrt(double(count))));
    for (std::size_t t = 0; t < count; ++t) {
        const mesh_data& mesh = assets.meshes.at(assets.terrain_meshes[t]);
        terrain_tile tile;
        tile.center = 0.5f * (mesh.bounds_min + mesh.bounds_max);
        tile.radius = glm::length(mesh.bounds_max - tile.center);
        tile.grids[0] = assets.terrain_meshes[t];
        tile.skirts.fill(scene_assets::k_no_skirt);
        tile.grid_count = std::uint8_t(std::max<std::size_t>(1, assets.terrain_grids.size()));
        for (std::size_t g = 0; g < assets.terrain_grids.size(); ++g) {
            tile.grids[g] = assets.terrain_grids[g].at(t);
            tile.skirts[g] = assets.terrain_skirts[g].at(t);
        }
        // The tiles lie row-major (models/terrain/terrain.h terrain_tile_meshes).
        if (side * side == std::int32_t(count)) {
            const auto x = std::int32_t(t) % side, z = std::int32_t(t) / side;
            tile.neighbours = {
                x > 0 ? std::int32_t(t) - 1 : -1, x + 1 < side ? std::int32_t(t) + 1 : -1,
                z > 0 ? std::int32_t(t) - side : -1, z + 1 < side ? std::int32_t(t) + side : -1};
        }
        tiles.push_back(tile);
    }
    return tiles;
}

}  // namespace

renderer::renderer(const renderer_settings& settings, const scene_assets& assets)
    : m_settings(settings),
      m_programs({settings.shadows, settings.id_buffer, settings.fade_dissolve, settings.toon,
                  settings.lines, !assets.shells.empty(),
                  !assets.shells.empty() && assets.shells.tiles.front().has_transfer(),
                  !assets.shells.empty() && assets.shells.implicit,
                  has_population_receivers(assets)}),
      m_ring(std::size_t(4) << 20),
      m_target(settings.width, settings.height, settings.id_buffer, settings.lines),
      m_textures(assets),
      m_sky(assets),
      m_commands(terrain_tiles_of(assets)),
      m_ground_uv_scale(assets.ground_uv_scale_m),
      m_terrain_resolution(assets.terrain.resolution),
      m_terrain_size_m(assets.terrain.size_m),
      m_shell_pass(assets) {
    for (std::size_t i = 0; i < assets.meshes.size(); ++i) {
        // Scenes built by hand (tests) may leave the library's mesh table empty: normal-lit.
        const lighting_variant lighting = i < assets.library.meshes.size()
                                              ? assets.library.meshes[i].lighting
                                              : lighting_variant::normal_mapped;
        const std::int32_t vertices_of = i < assets.library.meshes.size() ? assets.library.meshes[i].vertices_of : -1;
        std::uint16_t id = vertices_of >= 0 ? m_meshes.add_indices(std::uint16_t(vertices_of), assets.meshes[i], lighting)
                                            : m_meshes.add(assets.meshes[i], lighting);
        if (id != i) throw std::logic_error("renderer: mesh ids must follow scene_assets order");
        m_programs.prepare(m_meshes.get(id));
    }
    setup_instance_attributes(m_meshes.vertex_array());
    for (const species_entry& species : assets.library.species)
        m_lodf_clusters = std::max(m_lodf_clusters, species.lodf_clusters);
    if (settings.shadows)
        m_shadow_maps =
            std::make_unique<shadow_maps>(settings.shadow_resolution, settings.cascades);
    m_static_upload_bytes = m_meshes.uploaded_bytes() + m_textures.uploaded_bytes + m_shell_pass.uploaded_bytes();
    m_context.settings = &m_settings;
    m_context.programs = &m_programs;
    m_context.textures = &m_textures;
    m_context.commands = &m_commands;
    m_context.target = &m_target;
    m_context.shadows = m_shadow_maps.get();
    m_context.timer = &m_timer;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
}

renderer::~renderer() = default;

std::uint16_t renderer::add_mesh(const mesh_data& mesh) {
    const std::uint16_t id = m_meshes.add(mesh);
    m_programs.prepare(m_meshes.get(id));
    return id;
}

void frame_view::set_samples(const point_line_quality& quality) {
    splat_px = splat_size_px(quality);
    splat_plane =
        float(image_plane_units(splat_px, view_camera->fov_y, view_camera->viewport_height_px));
    sample_plane = float(image_plane_units(quality.sample_distance_px, view_camera->fov_y,
                                           view_camera->viewport_height_px));
    line_width_px = quality.sample_distance_px;
    sample_fog = quality.fog_weighted ? float(k_fog_density_per_m) : 0.0f;
    soft_splats = quality.splats == splat_style::soft;
    soft_splat_px = soft_splat_size_px(quality);
    soft_splat_alpha = soft_splat_peak_alpha(quality);
}

void renderer::write_uniforms(const frame_view& view) {
    const camera& cam = *view.view_camera;
    frame_uniforms u;
    u.view = cam.view;
    u.projection = cam.projection;
    u.view_projection = cam.projection * cam.view;
    u.inverse_view_projection = glm::inverse(u.view_projection);
    const int cascade_count = m_context.cascade_count;
    for (int c = 0; c < cascade_count; ++c) {
        u.cascade_view_projection[c] = view.cascades->light_view_projection[std::size_t(c)];
        u.cascade_split_far[c] = view.cascades->split_far[std::size_t(c)];
        u.cascade_texel_world[c] = view.cascades->texel_world_size[std::size_t(c)];
    }
    const sun& s = *view.sun_light;
    const bool sun_up = s.direction.y > -0.05f;
    u.sun_direction = glm::vec4(s.direction, cascade_count > 0 && sun_up ? 1.0f : 0.0f);
    u.sun_radiance =
        glm::vec4(sun_up ? s.color * s.intensity : glm::vec3(0.0f), float(cascade_count));
    for (int i = 0; i < 9; ++i)
        u.sh_irradiance[i] = glm::vec4(view.sky->irradiance_sh[std::size_t(i)], 0.0f);
    for (int i = 0; i < 9; ++i)
        u.sh_radiance[i] = glm::vec4(view.sky->radiance_sh[std::size_t(i)], 0.0f);
    u.terrain_map = terrain_map(view.terrain_position, m_terrain_resolution, m_terrain_size_m);
    u.terrain_params.w = m_textures.ground_normal ? 1.0f : 0.0f;
    m_terrain_shadow.uniforms(view.terrain_position, cascade_count > 0 && sun_up, u.terrain_params);
    const sh9 sun_basis = sh_basis(s.direction);
    for (int i = 0; i < 9; ++i) u.sun_sh[i / 4][i % 4] = sun_basis[std::size_t(i)];
    // Fog takes the sky's colour near the horizon, from the same SH (a horizontal normal).
    glm::vec3 horizon{0.0f};
    for (int i = 0; i < 9; ++i)
        horizon += view.sky->irradiance_sh[std::size_t(i)] * (i == 0 ? 0.282095f : 0.0f);
    u.fog = glm::vec4(horizon / std::numbers::pi_v<float> * 0.9f, float(k_fog_density_per_m));
    const float texel = m_shadow_maps ? 1.0f / float(m_shadow_maps->resolution()) : 0.0f;
    u.params = glm::vec4(m_settings.exposure, texel, view.time_s, 1.0f / m_ground_uv_scale);

    auto block = m_ring.allocate(sizeof(frame_uniforms), 256);
    std::memcpy(block.data, &u, sizeof(u));
    m_uniform_offset = std::size_t(block.offset);
    m_frame_upload_bytes += sizeof(u);
}

void renderer::write_instances(const frame_view& view) {
    // The LoDF slots' records first (their commands name them by slot), then the items', then
    // the terrain's (resources/draw_list.h instance_of_id).
    const auto& slots = view.draws->lodf_instances;
    const auto& instances = view.draws->instances;
    const std::size_t bytes = (slots.size() + instances.size() + 1) * sizeof(instance_gpu);
    auto block = m_ring.allocate(bytes, 256);
    auto* out = static_cast<std::byte*>(block.data);
    // An empty list's data() may be null, and memcpy from null is undefined even for 0 bytes.
    if (!slots.empty()) std::memcpy(out, slots.data(), slots.size() * sizeof(instance_gpu));
    out += slots.size() * sizeof(instance_gpu);
    if (!instances.empty()) std::memcpy(out, instances.data(), instances.size() * sizeof(instance_gpu));
    out += instances.size() * sizeof(instance_gpu);
    instance_gpu terrain;
    terrain.position = view.terrain_position;
    std::memcpy(out, &terrain, sizeof(terrain));
    glVertexArrayVertexBuffer(m_meshes.vertex_array(), k_instance_binding, m_ring.buffer(),
                              block.offset, sizeof(instance_gpu));
    m_frame_upload_bytes += bytes;
}

void renderer::render(const frame_view& view) {
    const auto start = std::chrono::steady_clock::now();
    m_context.view = &view;
    m_context.draw_calls = 0;
    m_context.cascade_count =
        m_shadow_maps ? std::min(view.cascades->count, m_shadow_maps->cascades()) : 0;
    const draw_list& draws = *view.draws;
    const std::size_t bytes_needed = sizeof(frame_uniforms) + 512 +
                                     (draws.lodf_instances.size() + draws.instances.size() + 1) * sizeof(instance_gpu) + 256 +
                                     m_commands.bytes_needed(draws) + 16 * 16;
    m_ring.begin_frame(bytes_needed);
    m_frame_upload_bytes = m_sky.update(*view.sky, *view.sun_light);
    // Only with shadows: without them nothing looks the terrain's shadow up.
    m_frame_upload_bytes +=
        m_terrain_shadow.update(m_context.cascade_count > 0 ? view.terrain_shadows : nullptr);
    write_uniforms(view);
    write_instances(view);
    m_frame_upload_bytes +=
        m_commands.write(view, m_meshes, m_context.cascade_count, m_ring, std::uint32_t(draws.lodf_instances.size()));
    update_lodf(view);
    m_record_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    glBindVertexArray(m_meshes.vertex_array());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, m_ring.buffer());
    m_context.frame_indirect_buffer = m_ring.buffer();
    glBindBufferRange(GL_UNIFORM_BUFFER, 0, m_ring.buffer(), GLintptr(m_uniform_offset),
                      sizeof(frame_uniforms));
    // No pass binds another texture to this unit, so it holds for the whole frame.
    if (m_terrain_shadow.casts()) glBindTextureUnit(k_terrain_shadow_unit, m_terrain_shadow.id());
    if (m_textures.ground_normal)
        glBindTextureUnit(k_ground_normal_unit, m_textures.ground_normal.id());
    for (frame_pass* pass : m_passes) pass->draw(m_context);
    m_ring.end_frame();
}

void renderer::update_lodf(const frame_view& view) {
    m_lodf_bytes = 0;
    if (m_lodf_clusters == 0 || !view.lodf || !view.library || view.lodf->slots.empty()) return;
    const lodf_slots& slots = *view.lodf;
    // The commands are sized by the first frame's slots (the scenario's lod.lodf_slots), which
    // spawn fixed for the world's life.
    if (!m_lodf || m_lodf_species.size() != slots.slots.size()) {
        m_lodf = std::make_unique<lodf_commands>(std::uint32_t(slots.slots.size()), m_lodf_clusters);
        m_lodf_species.assign(slots.slots.size(), k_no_lodf_slot);
        m_lodf_draw.set_commands(m_lodf.get());
    }
    for (std::uint32_t s = 0; s < slots.slots.size() && s < m_lodf_species.size(); ++s) {
        const lodf_slot& slot = slots.slots[s];
        if (slot.plant == k_no_lodf_slot) {
            if (m_lodf_species[s] != k_no_lodf_slot) m_lodf_bytes += m_lodf->release(s);
            m_lodf_species[s] = k_no_lodf_slot;
            continue;
        }
        const lodf_structure& lodf = view.library->lodf[slot.species];
        const std::span<const cluster_changes> clusters(view.lodf_clusters + std::size_t(s) * slots.clusters_per_slot,
                                                        lodf.clusters.size());
        if (slot.taken || m_lodf_species[s] != slot.species) {
            const gpu_submesh& foliage = m_meshes.get(view.library->species[slot.species].mesh_lodf_foliage).submeshes[0];
            m_lodf_bytes += m_lodf->assign(s, lodf, foliage, s, clusters);
            m_lodf_species[s] = slot.species;
        } else {
            m_lodf_bytes += m_lodf->update(s, clusters);
        }
    }
    m_frame_upload_bytes += m_lodf_bytes;
}

frame_stats renderer::finish() {
    glFinish();
    frame_stats stats;
    stats.work_counted = m_timer.has_counts();
    const auto work = m_timer.read_work();
    for (std::size_t p = 0; p < work.size(); ++p) {
        stats.pass_vertices[p] = work[p].vertices;
        stats.pass_primitives[p] = work[p].primitives;
        stats.pass_fragments[p] = work[p].fragments;
    }
    stats.gpu_pass_ms = m_timer.read();
    for (double ms : stats.gpu_pass_ms) stats.gpu_ms += ms;
    stats.upload_bytes = m_frame_upload_bytes;
    stats.lodf_command_bytes = m_lodf_bytes;
    stats.record_ms = m_record_ms;
    stats.draw_calls = m_context.draw_calls;
    stats.indirect_commands = m_commands.command_count();
    return stats;
}

void renderer::present(int window_width, int window_height) const {
    m_target.blit_to_default(window_width, window_height);
}

}  // namespace sylva::render
