#include "systems/render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_inverse.hpp>
#include <numbers>

#include "systems/build_draw_list_system.h"
#include "systems/cull_system.h"
#include "lighting/environment_map.h"
#include "lighting/fog.h"
#include "lighting/sky_model.h"
#include "lod/point_line_lod.h"
#include "systems/project_environment_system.h"
#include "systems/render/frame_uniforms.h"
#include "systems/render/textures.h"

namespace sylva::render {
namespace {

constexpr GLuint k_instance_binding = 1;
constexpr int k_sky_width = 128;
constexpr int k_sky_height = 64;

constexpr std::size_t material_index(material_kind m) { return static_cast<std::size_t>(m); }
constexpr std::uint32_t vertices_per(primitive_kind p) {
    return p == primitive_kind::triangles ? 3u : (p == primitive_kind::lines ? 2u : 1u);
}
constexpr GLenum gl_mode(primitive_kind p) {
    return p == primitive_kind::triangles ? GL_TRIANGLES : (p == primitive_kind::lines ? GL_LINES : GL_POINTS);
}
constexpr bool alpha_tested(material_kind m) {
    return m == material_kind::leaf || m == material_kind::billboard || m == material_kind::billboard_cloud;
}
static_assert(std::size_t(material_kind::billboard_cloud) == 4, "renderer k_materials counts material_kind");

void setup_instance_attributes(GLuint vao) {
    // instance_gpu (resources/draw_list.h): two vec4 attributes, advanced once per instance.
    glVertexArrayAttribFormat(vao, 3, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribFormat(vao, 4, 4, GL_FLOAT, GL_FALSE, 16);
    for (GLuint a : {3u, 4u}) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribBinding(vao, a, k_instance_binding);
    }
    glVertexArrayBindingDivisor(vao, k_instance_binding, 1);
}

// The sky's radiance on an equirectangular grid, matching the lookup in shaders/sky.frag.
void fill_sky_radiance_grid(const sky_model& sky, std::vector<float>& rgb) {
    rgb.resize(std::size_t(k_sky_width) * k_sky_height * 3);
    for (int j = 0; j < k_sky_height; ++j) {
        const float theta = (float(j) + 0.5f) / k_sky_height * std::numbers::pi_v<float>;
        for (int i = 0; i < k_sky_width; ++i) {
            const float phi = ((float(i) + 0.5f) / k_sky_width - 0.5f) * 2.0f * std::numbers::pi_v<float>;
            glm::vec3 d{std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
            glm::vec3 l = sky.radiance(d);
            std::memcpy(&rgb[(std::size_t(j) * k_sky_width + i) * 3], &l, sizeof(l));
        }
    }
}

// The environment map (k_sky_width x k_sky_height, rows from the zenith) turned by turn_deg
// of azimuth about the vertical: world column i shows the map at azimuth phi_i - turn, read
// with linear interpolation across columns (wrapping at south), scaled by `intensity`.
void fill_map_sky_grid(const std::vector<float>& map, float turn_deg, float intensity,
                       std::vector<float>& rgb) {
    rgb.resize(std::size_t(k_sky_width) * k_sky_height * 3);
    // A non-finite turn (no scenario gives one) draws the map unturned, as the SH are.
    const double shift = std::isfinite(turn_deg) ? double(turn_deg) / 360.0 * k_sky_width : 0.0;
    for (int i = 0; i < k_sky_width; ++i) {
        double source = std::fmod(double(i) - shift, double(k_sky_width));
        if (source < 0.0) source += k_sky_width;
        const auto left = int(source) % k_sky_width;
        const int right = (left + 1) % k_sky_width;
        const auto t = float(source - std::floor(source));
        for (int j = 0; j < k_sky_height; ++j) {
            const std::size_t row = std::size_t(j) * k_sky_width;
            for (int c = 0; c < 3; ++c) {
                const float a = map[(row + std::size_t(left)) * 3 + std::size_t(c)];
                const float b = map[(row + std::size_t(right)) * 3 + std::size_t(c)];
                rgb[(row + std::size_t(i)) * 3 + std::size_t(c)] = intensity * (a + (b - a) * t);
            }
        }
    }
}

bool same_sky(const sky_model& a, const sky_model& b) {
    return a.sun_direction == b.sun_direction && a.turbidity == b.turbidity && a.sky_intensity == b.sky_intensity &&
           a.ground_albedo == b.ground_albedo && a.sun_irradiance == b.sun_irradiance;
}

sky_model sky_of(const frame_view& view) {
    sky_model sky;
    sky.sun_direction = view.sun_light->direction;
    sky.turbidity = view.sky->turbidity;
    sky.sky_intensity = view.sky->sky_intensity;
    sky.ground_albedo = view.sky->ground_albedo;
    return sky;
}

}  // namespace

renderer::renderer(const renderer_settings& settings, const scene_assets& assets)
    : m_settings(settings), m_ring(std::size_t(4) << 20), m_target(settings.width, settings.height, settings.id_buffer),
      m_ground_uv_scale(assets.ground_uv_scale_m) {
    for (std::uint16_t id : assets.terrain_meshes) {
        const mesh_data& tile = assets.meshes.at(id);
        const glm::vec3 center = 0.5f * (tile.bounds_min + tile.bounds_max);
        m_terrain_tiles.push_back({id, center, glm::length(tile.bounds_max - center)});
    }
    for (std::size_t i = 0; i < assets.meshes.size(); ++i) {
        // Scenes built by hand (tests) may leave the library's mesh table empty: normal-lit.
        const lighting_variant lighting = i < assets.library.meshes.size()
                                              ? assets.library.meshes[i].lighting
                                              : lighting_variant::normal_mapped;
        std::uint16_t id = m_meshes.add(assets.meshes[i], lighting);
        if (id != i) throw std::logic_error("renderer: mesh ids must follow scene_assets order");
    }
    setup_instance_attributes(m_meshes.vertex_array());
    m_leaf_textures = make_texture_array(assets.leaf_textures, false, true);
    m_bark_textures = make_texture_array(assets.bark_textures, true);
    m_ground_texture = make_texture_array(std::span(&assets.ground_texture, 1), true);
    if (!assets.billboard_albedo.empty()) {
        m_billboard_albedo = make_texture_array(assets.billboard_albedo, false, true);
        m_billboard_normal = make_texture_array(assets.billboard_normal, false);
        if (!assets.billboard_transfer.empty())
            m_billboard_transfer = make_texture_array(assets.billboard_transfer, false);
    }
    if (!assets.cloud_albedo.empty()) {
        // The colour page's alpha is filtered plainly: the fade threshold reads the gaussian
        // in it. The normal page's alpha is the coverage the alpha test reads, kept per mip.
        // Pre-lit clouds read the page lit at bake time in its place (same layout and alpha).
        m_cloud_albedo = make_texture_array(assets.cloud_albedo, false);
        m_cloud_normal = make_texture_array(assets.cloud_normal, false, true);
        if (!assets.cloud_pre_lit.empty())
            m_cloud_pre_lit = make_texture_array(assets.cloud_pre_lit, false);
        if (!assets.cloud_transfer.empty())
            m_cloud_transfer = make_texture_array(assets.cloud_transfer, false);
    }
    write_species_block(assets);
    if (assets.environment_sky.width > 0)
        m_map_sky =
            downsample_environment_map(assets.environment_sky, k_sky_width, k_sky_height).rgb;
    if (settings.shadows)
        m_shadow_maps = std::make_unique<shadow_maps>(settings.shadow_resolution, settings.cascades);
    m_static_upload_bytes = m_meshes.uploaded_bytes();
    for (const auto* images :
         {&assets.leaf_textures, &assets.bark_textures, &assets.billboard_albedo,
          &assets.billboard_normal, &assets.cloud_albedo, &assets.cloud_normal,
          &assets.cloud_pre_lit, &assets.cloud_transfer, &assets.billboard_transfer})
        for (const auto& image : *images) m_static_upload_bytes += image.texels.size();
    m_static_upload_bytes += assets.ground_texture.texels.size();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
}

renderer::~renderer() = default;

// transfer.glsl's species_block, by texture layer: each species' sphere (centre height, radius
// around every representation) for shadow lookups outside the plant's own volume, and its first
// transfer-page layer. Only species lit by transfer read it, so only they count against its size.
void renderer::write_species_block(const scene_assets& assets) {
    std::array<glm::vec4, k_max_species_spheres> spheres{};
    for (const species_entry& e : assets.library.species) {
        if (e.lighting != lighting_variant::sh) continue;
        if (e.texture_layer >= float(k_max_species_spheres))
            throw std::runtime_error("renderer: species '" + e.name +
                                     "' is lit by SH transfer, which supports the first " +
                                     std::to_string(k_max_species_spheres) +
                                     " species of a scene only");
        spheres[std::size_t(e.texture_layer)] =
            glm::vec4(e.center_height, e.transfer_radius, e.transfer_layer, 0.0f);
    }
    // Billboards read their transfer from pages: a scene that lights them by transfer must have
    // them.
    for (std::size_t i = 0; i < assets.meshes.size() && i < assets.library.meshes.size(); ++i) {
        if (assets.library.meshes[i].lighting != lighting_variant::sh ||
            assets.meshes[i].submeshes.empty())
            continue;
        const material_kind m = assets.meshes[i].submeshes[0].material;
        if ((m == material_kind::billboard && assets.billboard_transfer.empty()) ||
            (m == material_kind::billboard_cloud && assets.cloud_transfer.empty()))
            throw std::logic_error("renderer: mesh " + std::to_string(i) +
                                   " is lit by SH transfer but has no transfer pages");
    }
    m_species_block = make_buffer();
    glNamedBufferStorage(m_species_block.id(), sizeof(spheres), spheres.data(), 0);
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

GLuint renderer::surface_program(material_kind material, bool shadow, primitive_kind primitive,
                                 lighting_variant lighting, sample_pass samples) {
    program_source source{"surface.vert", "surface.frag", {}, {}};
    if (primitive == primitive_kind::points) source.defines.push_back("PRIMITIVE_POINTS");
    if (samples == sample_pass::splat_visibility) {
        // Depth only (and the ID buffer's instance, which the blend pass does not write).
        source.defines.push_back("SPLAT_VISIBILITY");
        if (m_settings.id_buffer)
            source.defines.push_back("WRITE_ID");
        else
            source.fragment.clear();
        return m_shaders.program(source);
    }
    if (samples == sample_pass::soft_splats) source.defines.push_back("SOFT_SPLATS");
    if (primitive == primitive_kind::lines) {
        source.defines.push_back("PRIMITIVE_LINES");
        // d'-wide quads; GL's own one-pixel lines where d' is about a pixel, and in the shadow
        // cascades (one texel wide).
        if (!shadow && m_line_width_px > k_native_line_width_px) {
            source.geometry = "line.geom";
            source.defines.push_back("LINE_QUADS");
        }
    }
    if (material == material_kind::leaf) source.defines.push_back("MATERIAL_LEAF");
    if (material == material_kind::ground) source.defines.push_back("MATERIAL_GROUND");
    if (material == material_kind::billboard) source.defines.push_back("MATERIAL_BILLBOARD");
    if (material == material_kind::billboard_cloud) {
        source.defines.push_back("MATERIAL_BILLBOARD_CLOUD");
        if (lighting == lighting_variant::pre_lit) source.defines.push_back("CLOUD_PRE_LIT");
    }
    if (lighting == lighting_variant::sh && material != material_kind::ground)
        source.defines.push_back("SH_TRANSFER");
    // Partners of a transition are drawn in the view only, and only as whole meshes.
    if (!shadow && m_settings.fade_dissolve && primitive == primitive_kind::triangles &&
        material != material_kind::ground && material != material_kind::billboard_cloud)
        source.defines.push_back("FADE_DISSOLVE");
    // The soft splats' blend pass writes the splat layer's nearest depth where IDs would go.
    if (!shadow && m_settings.id_buffer && samples != sample_pass::soft_splats)
        source.defines.push_back("WRITE_ID");
    if (shadow) {
        source.defines.push_back("SHADOW_PASS");
        // Opaque casters need no fragment shader at all: depth only. Points and lines are
        // never alpha-tested (the bake put them on opaque texels).
        if (!alpha_tested(material) || primitive != primitive_kind::triangles) source.fragment.clear();
    }
    return m_shaders.program(source);
}

void renderer::update_sky_texture(const frame_view& view) {
    if (!m_map_sky.empty()) {
        // An environment map: only its turn and brightness change while the scene plays.
        const std::pair key{environment_map_turn_deg(*view.sky, *view.sun_light),
                            view.sky->sky_intensity};
        if (m_sky_texture && m_map_drawn == key) return;
        fill_map_sky_grid(m_map_sky, key.first, key.second > 0.0f ? key.second : 0.0f, m_sky_grid);
        upload_sky_grid();
        m_map_drawn = key;
        return;
    }
    // Keyed on the sky's inputs, not on environment::sky_revision: revisions count changes of
    // one environment, and two environments drawn by one renderer (the primitive-cost
    // calibration's and a scene's) can share a number while their skies differ.
    const sky_model sky = sky_of(view);
    if (m_sky_texture && m_sky_drawn && same_sky(*m_sky_drawn, sky)) return;
    fill_sky_radiance_grid(sky, m_sky_grid);
    upload_sky_grid();
    m_sky_drawn = sky;
}

void renderer::upload_sky_grid() {
    const std::vector<float>& grid = m_sky_grid;
    if (!m_sky_texture)
        m_sky_texture = make_float_texture(k_sky_width, k_sky_height, grid.data());
    else  // the sun moved: same texture, new texels (no GL allocation in the frame loop)
        glTextureSubImage2D(m_sky_texture.id(), 0, 0, 0, k_sky_width, k_sky_height, GL_RGB,
                            GL_FLOAT, grid.data());
    m_frame_upload_bytes += grid.size() * sizeof(float);
}

void renderer::write_uniforms(const frame_view& view) {
    const camera& cam = *view.view_camera;
    frame_uniforms u;
    u.view = cam.view;
    u.projection = cam.projection;
    u.view_projection = cam.projection * cam.view;
    u.inverse_view_projection = glm::inverse(u.view_projection);
    m_cascade_count = m_shadow_maps ? std::min(view.cascades->count, m_shadow_maps->cascades()) : 0;
    m_cascades_holding_receivers = view.cascades->holds_receivers;
    for (int c = 0; c < m_cascade_count; ++c) {
        u.cascade_view_projection[c] = view.cascades->light_view_projection[std::size_t(c)];
        u.cascade_split_far[c] = view.cascades->split_far[std::size_t(c)];
        u.cascade_texel_world[c] = view.cascades->texel_world_size[std::size_t(c)];
    }
    const sun& s = *view.sun_light;
    const bool sun_up = s.direction.y > -0.05f;
    u.sun_direction = glm::vec4(s.direction, m_cascade_count > 0 && sun_up ? 1.0f : 0.0f);
    u.sun_radiance = glm::vec4(sun_up ? s.color * s.intensity : glm::vec3(0.0f), float(m_cascade_count));
    for (int i = 0; i < 9; ++i) u.sh_irradiance[i] = glm::vec4(view.sky->irradiance_sh[std::size_t(i)], 0.0f);
    for (int i = 0; i < 9; ++i)
        u.sh_radiance[i] = glm::vec4(view.sky->radiance_sh[std::size_t(i)], 0.0f);
    const sh9 sun_basis = sh_basis(s.direction);
    for (int i = 0; i < 9; ++i) u.sun_sh[i / 4][i % 4] = sun_basis[std::size_t(i)];
    // Fog takes the sky's colour near the horizon, from the same SH (a horizontal normal).
    glm::vec3 horizon{0.0f};
    for (int i = 0; i < 9; ++i) horizon += view.sky->irradiance_sh[std::size_t(i)] * (i == 0 ? 0.282095f : 0.0f);
    u.fog = glm::vec4(horizon / std::numbers::pi_v<float> * 0.9f, float(k_fog_density_per_m));
    const float texel = m_shadow_maps ? 1.0f / float(m_shadow_maps->resolution()) : 0.0f;
    u.params = glm::vec4(m_settings.exposure, texel, view.time_s, 1.0f / m_ground_uv_scale);

    auto block = m_ring.allocate(sizeof(frame_uniforms), 256);
    std::memcpy(block.data, &u, sizeof(u));
    m_uniform_offset = std::size_t(block.offset);
    m_frame_upload_bytes += sizeof(u);
}

void renderer::write_instances(const frame_view& view) {
    const auto& instances = view.draws->instances;
    const std::size_t bytes = (instances.size() + 1) * sizeof(instance_gpu);
    auto block = m_ring.allocate(bytes, 256);
    // An empty list's data() may be null, and memcpy from null is undefined even for 0 bytes.
    if (!instances.empty())
        std::memcpy(block.data, instances.data(), instances.size() * sizeof(instance_gpu));
    instance_gpu terrain;
    terrain.position = view.terrain_position;
    std::memcpy(static_cast<std::byte*>(block.data) + instances.size() * sizeof(instance_gpu), &terrain,
                sizeof(terrain));
    glVertexArrayVertexBuffer(m_meshes.vertex_array(), k_instance_binding, m_ring.buffer(),
                              block.offset, sizeof(instance_gpu));
    m_frame_upload_bytes += bytes;
}

void renderer::write_commands(const frame_view& view) {
    const draw_list& draws = *view.draws;
    // Group commands by (pass, material): each group is one glMultiDrawElementsIndirect.
    static_assert(sizeof(indirect_command) == 20);
    auto& groups = m_command_groups;
    for (auto& g : groups) g.clear();
    // `primitives` > 0 draws that many primitives from the start of each submesh (a prefix,
    // Deussen 2002 §5.3); 0 draws them all.
    auto add = [&](render_pass pass, const gpu_mesh& mesh, std::uint32_t first, std::uint32_t count,
                   std::uint32_t primitives = 0) {
        const std::uint32_t per = vertices_per(mesh.primitive);
        for (const auto& sub : mesh.submeshes) {
            const std::uint32_t indices = primitives ? std::min(primitives * per, sub.index_count) : sub.index_count;
            groups[std::size_t(pass) * k_groups_per_pass +
                   group_of(sub.material, mesh.primitive, sub.lighting)]
                .push_back({indices, count, sub.first_index, sub.base_vertex, first});
        }
    };
    for (const auto& batch : draws.batches) {
        if (is_shadow_pass(batch.pass) && int(batch.pass) >= m_cascade_count) continue;
        add(batch.pass, m_meshes.get(batch.mesh), batch.first_instance, batch.instance_count, batch.count);
    }
    // Terrain tiles: each one drawn where its bounding sphere meets the view or a cascade.
    const auto terrain_instance = std::uint32_t(draws.instances.size());
    const camera& cam = *view.view_camera;
    const frustum_planes frustum = extract_frustum_planes(cam.projection * cam.view);
    std::array<cascade_bounds, k_max_cascades> cascades{};
    for (int c = 0; c < m_cascade_count; ++c) {
        cascades[std::size_t(c)] = make_cascade_bounds(view.cascades->light_view_projection[std::size_t(c)]);
        cascades[std::size_t(c)].holds_receivers = view.cascades->holds_receivers[std::size_t(c)];
    }
    for (const terrain_tile& tile : m_terrain_tiles) {
        const glm::vec3 center = view.terrain_position + tile.center;
        if (sphere_in_frustum(frustum, center, tile.radius))
            add(render_pass::opaque, m_meshes.get(tile.mesh), terrain_instance, 1);
        for (int c = 0; c < m_cascade_count; ++c)
            if (sphere_overlaps_cascade(cascades[std::size_t(c)], center, tile.radius))
                add(shadow_pass(c), m_meshes.get(tile.mesh), terrain_instance, 1);
    }

    m_indirect_commands = 0;
    for (std::size_t g = 0; g < k_command_groups; ++g) {
        auto& range = m_commands[g / k_groups_per_pass][g % k_groups_per_pass];
        range = {};
        if (groups[g].empty()) continue;
        const std::size_t bytes = groups[g].size() * sizeof(indirect_command);
        auto block = m_ring.allocate(bytes, 16);
        std::memcpy(block.data, groups[g].data(), bytes);
        range = {std::size_t(block.offset), std::uint32_t(groups[g].size())};
        m_indirect_commands += range.count;
        m_frame_upload_bytes += bytes;
    }
}

void renderer::draw_group(const command_range& range, GLuint program, bool cull_back_faces,
                          primitive_kind primitive) {
    if (range.count == 0) return;
    glUseProgram(program);
    if (cull_back_faces)
        glEnable(GL_CULL_FACE);
    else
        glDisable(GL_CULL_FACE);
    glMultiDrawElementsIndirect(gl_mode(primitive), GL_UNSIGNED_INT,
                                reinterpret_cast<const void*>(range.offset), GLsizei(range.count), 0);
    ++m_draw_calls;
}

void renderer::draw_shadow_cascades() {
    if (m_cascade_count == 0) return;
    m_timer.begin(gpu_pass::shadow);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);
    for (int c = 0; c < m_cascade_count; ++c) {
        // No surface samples a cascade whose slice holds no receiver (fit_shadow_cascades).
        if (!m_cascades_holding_receivers[std::size_t(c)]) continue;
        m_shadow_maps->bind_layer(c);
        const GLuint ground = surface_program(material_kind::ground, true);
        glUseProgram(ground);
        glUniform1i(glGetUniformLocation(ground, "u_cascade"), c);
        const auto& groups = m_commands[std::size_t(shadow_pass(c))];
        draw_group(groups[group_of(material_kind::ground, primitive_kind::triangles)], ground, false);
        // Depth only: every lighting variant's group is drawn with the one shadow program.
        for (const lighting_variant l : k_all_lightings) {
            const GLuint bark = surface_program(material_kind::bark, true);
            glUseProgram(bark);
            glUniform1i(glGetUniformLocation(bark, "u_cascade"), c);
            draw_group(groups[group_of(material_kind::bark, primitive_kind::triangles, l)], bark,
                       false);
            const GLuint leaf = surface_program(material_kind::leaf, true);
            glUseProgram(leaf);
            glUniform1i(glGetUniformLocation(leaf, "u_cascade"), c);
            glBindTextureUnit(0, m_leaf_textures.id());
            draw_group(groups[group_of(material_kind::leaf, primitive_kind::triangles, l)], leaf,
                       false);
            if (groups[group_of(material_kind::billboard, primitive_kind::triangles, l)].count) {
                const GLuint billboard = surface_program(material_kind::billboard, true);
                glUseProgram(billboard);
                glUniform1i(glGetUniformLocation(billboard, "u_cascade"), c);
                glBindTextureUnit(0, m_billboard_albedo.id());
                draw_group(groups[group_of(material_kind::billboard, primitive_kind::triangles, l)],
                           billboard, false);
            }
        }
        draw_clouds(groups, c);
        draw_samples(groups, sample_pass::cascade, c);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    m_timer.end();
}

void renderer::draw_opaque() {
    m_timer.begin(gpu_pass::opaque);
    m_target.bind();
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    if (m_target.has_id_buffer()) {
        m_target.draw_ids(true);
        const GLuint none = 0;
        glClearBufferuiv(GL_COLOR, 1, &none);
    }
    if (m_shadow_maps) glBindTextureUnit(1, m_shadow_maps->texture());
    const auto& groups = m_commands[std::size_t(render_pass::opaque)];
    glBindTextureUnit(0, m_ground_texture.id());
    draw_group(groups[group_of(material_kind::ground, primitive_kind::triangles)], surface_program(material_kind::ground, false), true);
    if (!m_species_block.id()) throw std::logic_error("renderer: no species block");
    glBindBufferBase(GL_UNIFORM_BUFFER, 1, m_species_block.id());
    for (const lighting_variant l : k_all_lightings) {
        glBindTextureUnit(0, m_bark_textures.id());
        draw_group(groups[group_of(material_kind::bark, primitive_kind::triangles, l)],
                   surface_program(material_kind::bark, false, primitive_kind::triangles, l), true);
        glBindTextureUnit(0, m_leaf_textures.id());
        draw_group(groups[group_of(material_kind::leaf, primitive_kind::triangles, l)],
                   surface_program(material_kind::leaf, false, primitive_kind::triangles, l),
                   false);
        if (groups[group_of(material_kind::billboard, primitive_kind::triangles, l)].count) {
            glBindTextureUnit(0, m_billboard_albedo.id());
            glBindTextureUnit(2, m_billboard_normal.id());
            if (l == lighting_variant::sh) glBindTextureUnit(3, m_billboard_transfer.id());
            draw_group(
                groups[group_of(material_kind::billboard, primitive_kind::triangles, l)],
                surface_program(material_kind::billboard, false, primitive_kind::triangles, l),
                false);
        }
    }
    draw_clouds(groups, -1);
    draw_samples(groups, sample_pass::view);
    m_timer.end();
}

// Soft splats (lod/point_line_lod.h), after the sky so that they blend over it: opaque
// splats pushed back by ε into depth only (and IDs), then the Gaussians, depth-tested against
// that and blended "over" without writing depth. Splats of at least k_splat_layer_min_side_px
// are drawn into the half-size splat layer (splat_layer.h), each keeping the nearest splat
// depth, and the layer is filtered up over the frame at that depth (with an ID buffer, its IDs
// with it); smaller ones straight into the frame. The target's alpha is kept.
void renderer::draw_soft_splats() {
    const auto& groups = m_commands[std::size_t(render_pass::opaque)];
    bool any = false;
    for (const lighting_variant l : k_all_lightings)
        for (const material_kind m : {material_kind::bark, material_kind::leaf})
            any = any || groups[group_of(m, primitive_kind::points, l)].count > 0;
    if (!any) return;
    m_timer.begin(gpu_pass::splats);
    const bool layered = m_soft_splat_px >= k_splat_layer_min_side_px;
    // Splats keep their size in the frame: in layer pixels they are k_scale as wide.
    const float pixel_scale = layered ? splat_layer::k_scale : 1.0f;
    if (layered) {
        if (!m_splat_layer)
            m_splat_layer.emplace(m_settings.width, m_settings.height, m_settings.id_buffer);
        m_splat_layer->begin();
        if (m_shadow_maps) glBindTextureUnit(1, m_shadow_maps->texture());  // the splats' lighting
    }
    glDepthMask(GL_TRUE);
    if (layered) {
        m_splat_layer->draw_visibility();
    } else {
        glColorMaski(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        m_target.draw_ids(true);
    }
    draw_samples(groups, sample_pass::splat_visibility, -1, pixel_scale);
    if (layered) {
        m_splat_layer->draw_blend();
    } else {
        glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        m_target.draw_ids(false);
    }
    glDepthMask(GL_FALSE);
    glEnablei(GL_BLEND, 0);
    // Into the layer: premultiplied "over" with its coverage in alpha, and the nearest splat
    // depth beside it; into the frame: "over", the target's alpha kept.
    glBlendFuncSeparatei(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, layered ? GL_ONE : GL_ZERO,
                         layered ? GL_ONE_MINUS_SRC_ALPHA : GL_ONE);
    if (layered) {
        glEnablei(GL_BLEND, 1);
        glBlendEquationi(1, GL_MIN);
    }
    draw_samples(groups, sample_pass::soft_splats, -1, pixel_scale);
    if (layered) glBlendEquationi(1, GL_FUNC_ADD);
    glDisable(GL_BLEND);
    if (layered) composite_splat_layer();
    glDepthMask(GL_TRUE);
    m_timer.end();
}

// Draws the splat layer over the frame (shaders/splat_layer.frag), then, when the frame has an
// ID buffer, the layer's visibility IDs in a second pass that writes nothing else.
void renderer::composite_splat_layer() {
    m_target.bind();
    glBindTextureUnit(0, m_splat_layer->color());
    glBindTextureUnit(1, m_splat_layer->nearest_depth());
    glEnablei(GL_BLEND, 0);
    glBlendFuncSeparatei(0, GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    glUseProgram(m_shaders.program({"sky.vert", "splat_layer.frag", {}, {}}));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++m_draw_calls;
    glDisable(GL_BLEND);
    if (m_splat_layer->ids() != 0) {
        glBindTextureUnit(2, m_splat_layer->ids());
        m_target.draw_ids(true);
        glColorMaski(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glUseProgram(m_shaders.program({"sky.vert", "splat_layer.frag", {"WRITE_ID"}, {}}));
        glDrawArrays(GL_TRIANGLES, 0, 3);
        ++m_draw_calls;
        glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        m_target.draw_ids(false);
    }
}

// The point and line representation's samples (Deussen 2002 §5.1, §5.2) of bark and leaf
// parts: into shadow cascade `cascade`, the view's opaque pass, or one of the two passes of
// soft splats (draw_soft_splats).
void renderer::draw_samples(const pass_commands& groups, sample_pass pass, int cascade,
                            float pixel_scale) {
    const bool shadow = pass == sample_pass::cascade;
    const bool soft = pass == sample_pass::splat_visibility || pass == sample_pass::soft_splats;
    for (const lighting_variant lighting : k_all_lightings)
        for (const primitive_kind primitive : {primitive_kind::points, primitive_kind::lines}) {
            // Soft passes draw points only; the view's opaque samples leave soft points out.
            if (soft && primitive != primitive_kind::points) continue;
            if (pass == sample_pass::view && primitive == primitive_kind::points && m_soft_splats)
                continue;
            for (const material_kind material : {material_kind::bark, material_kind::leaf}) {
                const command_range& range = groups[group_of(material, primitive, lighting)];
                if (range.count == 0) continue;
                // Shadows and the visibility pass are depth only: one program for every variant.
                const bool depth_only = shadow || pass == sample_pass::splat_visibility;
                const GLuint program =
                    surface_program(material, shadow, primitive,
                                    depth_only ? lighting_variant::normal_mapped : lighting, pass);
                glUseProgram(program);
                if (shadow) glUniform1i(glGetUniformLocation(program, "u_cascade"), cascade);
                if (pass == sample_pass::splat_visibility) {
                    glUniform1f(glGetUniformLocation(program, "u_depth_push"),
                                k_soft_splat_depth_offset * m_splat_plane);
                    glUniform1i(glGetUniformLocation(program, "u_visibility_stride"),
                                k_soft_splat_visibility_stride);
                }
                if (pass == sample_pass::soft_splats)
                    glUniform1f(glGetUniformLocation(program, "u_soft_alpha"), m_soft_splat_alpha);
                if (primitive == primitive_kind::points) {
                    glEnable(GL_PROGRAM_POINT_SIZE);
                    glUniform1f(glGetUniformLocation(program, "u_splat_px"),
                                pixel_scale * (pass == sample_pass::soft_splats ? m_soft_splat_px
                                                                                : m_splat_px));
                    // A cascade's splats are as wide as its samples are apart (c_p = 1,
                    // compute_shadow_prefix): k_shadow_sample_texels texels, or
                    // k_shadow_sample_spacing times the viewer's sample distance there.
                    glUniform1f(
                        glGetUniformLocation(program, "u_splat_plane"),
                        shadow ? float(k_shadow_sample_spacing) * m_sample_plane : m_splat_plane);
                    if (shadow) {
                        glUniform1f(glGetUniformLocation(program, "u_splat_texels"),
                                    float(k_shadow_sample_texels));
                        glUniform1f(glGetUniformLocation(program, "u_shadow_push"),
                                    float(k_shadow_splat_push));
                    } else {
                        glUniform1f(glGetUniformLocation(program, "u_sample_fog"), m_sample_fog);
                        glUniform1f(glGetUniformLocation(program, "u_sample_growth_max"),
                                    float(k_fog_sample_growth_max));
                    }
                } else if (!shadow && m_line_width_px > k_native_line_width_px) {
                    glUniform1f(glGetUniformLocation(program, "u_line_width_px"), m_line_width_px);
                    glUniform2f(glGetUniformLocation(program, "u_viewport_px"),
                                float(m_settings.width), float(m_settings.height));
                }
                glBindTextureUnit(0, material == material_kind::leaf ? m_leaf_textures.id()
                                                                     : m_bark_textures.id());
                draw_group(range, program, false, primitive);
            }
        }
}

// Billboard-cloud quads (models/bake/billboard_cloud.h) of every lighting variant, in a shadow
// cascade (`cascade` >= 0) or the view (-1). One-sided: each side of a billboard shows only to
// its own viewer. In a cascade, both sides of a billboard share its plane and silhouette (the
// back image is the front's mirror): culling the side turned away from the sun leaves one quad
// per billboard and the same shadow, at half the alpha-tested fragments.
void renderer::draw_clouds(const pass_commands& groups, int cascade) {
    const bool shadow = cascade >= 0;
    for (const lighting_variant l : k_all_lightings) {
        const command_range& range =
            groups[group_of(material_kind::billboard_cloud, primitive_kind::triangles, l)];
        if (range.count == 0) continue;
        const GLuint program =
            surface_program(material_kind::billboard_cloud, shadow, primitive_kind::triangles,
                            shadow ? lighting_variant::normal_mapped : l);
        glUseProgram(program);
        if (shadow) glUniform1i(glGetUniformLocation(program, "u_cascade"), cascade);
        // Pre-lit clouds read the page lit at bake time in the colour page's place (same layout
        // and alpha); SH clouds add their transfer pages.
        glBindTextureUnit(0, !shadow && l == lighting_variant::pre_lit ? m_cloud_pre_lit.id()
                                                                       : m_cloud_albedo.id());
        glBindTextureUnit(2, m_cloud_normal.id());
        if (!shadow && l == lighting_variant::sh) glBindTextureUnit(3, m_cloud_transfer.id());
        draw_group(range, program, true);
    }
}

void renderer::draw_sky() {
    // Drawn last at the far plane: only pixels no surface covered are shaded.
    m_timer.begin(gpu_pass::sky);
    m_target.draw_ids(false);  // the sky leaves ID 0
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glUseProgram(m_shaders.program({"sky.vert", "sky.frag", {}, {}}));
    glBindTextureUnit(0, m_sky_texture.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++m_draw_calls;
    glDepthMask(GL_TRUE);
    m_timer.end();
}

void renderer::render(const frame_view& view) {
    const auto start = std::chrono::steady_clock::now();
    m_frame_upload_bytes = 0;
    m_draw_calls = 0;
    m_splat_px = view.splat_px;
    m_splat_plane = view.splat_plane;
    m_sample_plane = view.sample_plane;
    m_sample_fog = view.sample_fog;
    m_line_width_px = view.line_width_px;
    m_soft_splats = view.soft_splats;
    m_soft_splat_px = view.soft_splat_px;
    m_soft_splat_alpha = view.soft_splat_alpha;
    const auto& draws = *view.draws;
    std::size_t commands = (draws.batches.size() + m_terrain_tiles.size() * 5 + 8) * k_materials;
    std::size_t bytes_needed = sizeof(frame_uniforms) + 512 +
                               (draws.instances.size() + 1) * sizeof(instance_gpu) + 256 +
                               commands * sizeof(indirect_command) + 16 * 16;
    m_ring.begin_frame(bytes_needed);
    update_sky_texture(view);
    write_uniforms(view);
    write_instances(view);
    write_commands(view);
    m_record_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    glBindVertexArray(m_meshes.vertex_array());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, m_ring.buffer());
    glBindBufferRange(GL_UNIFORM_BUFFER, 0, m_ring.buffer(), GLintptr(m_uniform_offset),
                      sizeof(frame_uniforms));
    draw_shadow_cascades();
    draw_opaque();
    draw_sky();
    if (m_soft_splats) draw_soft_splats();
    m_ring.end_frame();
}

frame_stats renderer::finish() {
    glFinish();
    frame_stats stats;
    stats.gpu_pass_ms = m_timer.read();
    for (double ms : stats.gpu_pass_ms) stats.gpu_ms += ms;
    stats.upload_bytes = m_frame_upload_bytes;
    stats.record_ms = m_record_ms;
    stats.draw_calls = m_draw_calls;
    stats.indirect_commands = m_indirect_commands;
    return stats;
}

void renderer::present(int window_width, int window_height) const {
    m_target.blit_to_default(window_width, window_height);
}

}  // namespace sylva::render
