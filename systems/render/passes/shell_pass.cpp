#include "systems/render/passes/shell_pass.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <tuple>
#include <stdexcept>
#include <string>
#include <glm/geometric.hpp>

#include "lod/shell_blending.h"
#include "lod/shell_canopy.h"
#include "lod/shell_slanting.h"
#include "models/bake/transfer_pages.h"
#include "models/terrain/terrain.h"
#include "models/terrain/wang_tiles.h"
#include "systems/render/renderer.h"
#include "systems/render/textures.h"

namespace sylva::render {
namespace {

struct shell_vertex {
    glm::vec3 position;
    glm::vec3 centre;
    float radius;  // the triangle's: the largest distance of its vertices from the centre
};
static_assert(sizeof(shell_vertex) == 28);

}  // namespace

shell_pass::uniform_locations shell_pass::uniforms_of(GLuint program) {
    uniform_locations u;
    u.program = program;
    u.terrain_position = glGetUniformLocation(program, "u_terrain_position");
    u.slice_height = glGetUniformLocation(program, "u_slice_height");
    u.slant = glGetUniformLocation(program, "u_slant");
    u.slant_reach = glGetUniformLocation(program, "u_slant_reach");
    u.premultiplied = glGetUniformLocation(program, "u_premultiplied");
    u.lattice = glGetUniformLocation(program, "u_lattice");
    u.area = glGetUniformLocation(program, "u_area");
    u.layers_per_tile = glGetUniformLocation(program, "u_layers_per_tile");
    u.fade = glGetUniformLocation(program, "u_fade");
    u.level = glGetUniformLocation(program, "u_level");
    u.max_level = glGetUniformLocation(program, "u_max_level");
    u.level_criterion = glGetUniformLocation(program, "u_level_criterion");
    u.level_slices = glGetUniformLocation(program, "u_level_slices");
    u.level_first_layer = glGetUniformLocation(program, "u_level_first_layer");
    u.footprint_scale = glGetUniformLocation(program, "u_footprint_scale");
    return u;
}

shell_pass::shell_pass(const scene_assets& assets) {
    const shell_textures& shells = assets.shells;
    if (shells.empty()) return;
    m_slices = std::uint32_t(shells.tiles.front().colour.size());
    m_slice_height = shells.tiles.front().slice_height_m;
    // Level L holds ⌈S / 2^L⌉ slices, each pair of the level below merged (lod/shell_blending.h).
    // The vertex shader's level arrays hold 16 (shaders/shell.vert k_max_levels): 32,768 slices.
    if (shell_pyramid_levels(m_slices) > 16)
        throw std::runtime_error("shell textures of " + std::to_string(m_slices) + " slices: at most 32768");
    for (std::uint32_t level = 0; level < shell_pyramid_levels(m_slices); ++level) {
        m_level_first_layer.push_back(GLint(m_layers_per_tile));
        m_level_slices.push_back(GLint(shell_slices_at_level(m_slices, level)));
        m_layers_per_tile += std::uint32_t(m_level_slices.back());
    }
    std::vector<image_rgba8> colour;
    std::vector<image_rgba8> normal;
    // Lit by transfer, the slices need no normals: that array is neither merged nor uploaded.
    const bool by_transfer = shells.tiles.front().has_transfer();
    std::vector<std::vector<image_rgba8>> transfer(by_transfer ? k_transfer_pages : 0);
    m_standard_blending = shells.standard_blending;
    for (const shell_stack& stack : shells.tiles) {
        std::vector<image_rgba8> c = stack.colour;
        if (m_standard_blending)
            for (image_rgba8& slice : c) slice = unpremultiply_slice(slice);
        std::vector<image_rgba8> n = by_transfer ? std::vector<image_rgba8>{} : stack.normal;
        std::vector<image_rgba8> t = stack.transfer;
        for (;;) {
            colour.insert(colour.end(), c.begin(), c.end());
            // The normals' alpha (coverage, which the next level merges by) is uploaded as the
            // sun left by the slices above (lod/shell_canopy.h).
            if (!n.empty()) {
                const std::vector<image_rgba8> lit = with_canopy_transmittance(n, c);
                normal.insert(normal.end(), lit.begin(), lit.end());
            }
            for (std::size_t k = 0; k < t.size(); ++k) transfer[k % k_transfer_pages].push_back(t[k]);
            if (c.size() == 1) break;
            c = m_standard_blending ? next_pyramid_level_standard(c) : next_pyramid_level(c);
            if (!n.empty()) n = next_normal_pyramid_level(n);
            if (!t.empty()) t = next_transfer_pyramid_level(t);
        }
    }
    m_colour = make_texture_array(colour, false);
    for (const image_rgba8& i : colour) m_uploaded_bytes += i.texels.size() * 4 / 3;  // with mips
    if (!normal.empty()) {
        m_normal = make_texture_array(normal, false);
        for (const image_rgba8& i : normal) m_uploaded_bytes += i.texels.size() * 4 / 3;
    }
    for (const std::vector<image_rgba8>& page : transfer) {
        m_transfer.push_back(make_texture_array(page, false));
        for (const image_rgba8& i : page) m_uploaded_bytes += i.texels.size() * 4 / 3;
    }
    m_lit_for.fill(std::numeric_limits<float>::quiet_NaN());
    m_last_light.fill(std::numeric_limits<float>::quiet_NaN());
    if (!transfer.empty()) {
        m_transfer_texels = GLsizei(transfer.front().front().width);
        m_transfer_layers = GLsizei(transfer.front().size());
        const int levels = std::bit_width(std::uint32_t(m_transfer_texels));
        for (auto [texture, format, bytes] : {std::tuple{&m_lit_seen, GL_RGBA16F, 8}, {&m_lit_other, GL_R16F, 2}}) {
            *texture = make_texture(GL_TEXTURE_2D_ARRAY);
            glTextureStorage3D(texture->id(), levels, format, m_transfer_texels, m_transfer_texels, m_transfer_layers);
            // As the colour arrays are sampled (systems/render/textures.cpp make_texture_array).
            glTextureParameteri(texture->id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(texture->id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            glTextureParameteri(texture->id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
            glTextureParameteri(texture->id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            m_uploaded_bytes += std::uint64_t(m_transfer_texels) * std::uint64_t(m_transfer_texels) *
                                std::uint64_t(m_transfer_layers) * std::uint64_t(bytes) * 4 / 3;
        }
    }
    // The tiling over the terrain: one texel per lattice cell, terrain-local.
    const double t = shells.tile_size_m;
    const heightfield& ground = assets.terrain;
    const double half = 0.5 * double(ground.size_m);
    const auto cells = std::int64_t(std::ceil((2.0 * half) / t)) + 1;
    std::vector<std::uint16_t> index(std::size_t(cells * cells));
    const auto first_i = std::int64_t(std::floor((-half - shells.origin.x) / t));
    const auto first_j = std::int64_t(std::floor((-half - shells.origin.y) / t));
    for (std::int64_t j = 0; j < cells; ++j)
        for (std::int64_t i = 0; i < cells; ++i)
            index[std::size_t(j * cells + i)] =
                std::uint16_t(wang_tile_at(shells.tiling_seed, first_i + i, first_j + j, shells.colours));
    m_index = make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(m_index.id(), 1, GL_R16UI, GLsizei(cells), GLsizei(cells));
    // An integer texture with GL's default linear filters is incomplete and reads as 0.
    glTextureParameteri(m_index.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(m_index.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    // Rows of 2-byte texels: GL's default unpack alignment of 4 would skew every odd-width row.
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glTextureSubImage2D(m_index.id(), 0, 0, 0, GLsizei(cells), GLsizei(cells), GL_RED_INTEGER, GL_UNSIGNED_SHORT,
                        index.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    m_uploaded_bytes += index.size() * 2;
    m_area = {float(shells.area[0]), float(shells.area[1]), float(shells.area[2]), float(shells.area[3])};
    m_lattice = {float(shells.origin.x + double(first_i) * t), float(shells.origin.y + double(first_j) * t), float(t),
                 float(1.0 / t)};
    // The terrain's triangles on every grid of the ground (resources/scene_assets.h terrain_grids,
    // which components/shell_tile.h's grids are; the terrain's own tiles alone when it has none),
    // each vertex with its triangle's centre (Eq. 2 needs m), grid by grid within each tile.
    std::vector<shell_vertex> vertices;
    const std::size_t grids = std::max<std::size_t>(1, assets.terrain_grids.size());
    m_tile_ranges.assign(assets.terrain_meshes.size(), {});
    for (std::size_t g = 0; g < grids; ++g) {
        for (std::size_t n = 0; n < m_tile_ranges.size(); ++n) {
            const mesh_data& tile =
                assets.meshes.at(g == 0 ? assets.terrain_meshes[n] : assets.terrain_grids[g][n]);
            const auto first = std::uint32_t(vertices.size());
            for (std::size_t k = 0; k + 2 < tile.indices.size(); k += 3) {
                const vertex* v[3] = {&tile.vertices[tile.indices[k]], &tile.vertices[tile.indices[k + 1]],
                                      &tile.vertices[tile.indices[k + 2]]};
                const glm::vec3 centre = (v[0]->position + v[1]->position + v[2]->position) / 3.0f;
                const float radius = triangle_reach(v[0]->position, v[1]->position, v[2]->position);
                for (const vertex* p : v) vertices.push_back({p->position, centre, radius});
            }
            m_tile_ranges[n].push_back({first, std::uint32_t(vertices.size()) - first});
        }
    }
    m_vertices = make_buffer();
    glNamedBufferStorage(m_vertices.id(), GLsizeiptr(vertices.size() * sizeof(shell_vertex)), vertices.data(), 0);
    m_uploaded_bytes += vertices.size() * sizeof(shell_vertex);
    m_vertex_array = make_vertex_array();
    const GLuint vao = m_vertex_array.id();
    glVertexArrayVertexBuffer(vao, 0, m_vertices.id(), 0, sizeof(shell_vertex));
    for (GLuint a = 0; a < 3; ++a) {
        glVertexArrayAttribFormat(vao, a, a < 2 ? 3 : 1, GL_FLOAT, GL_FALSE, a * 12);
        glVertexArrayAttribBinding(vao, a, 0);
        glEnableVertexArrayAttrib(vao, a);
    }
}

bool shell_pass::relight(pass_context& context) {
    const frame_view& view = *context.view;
    std::array<float, 30> light{};
    for (std::size_t i = 0; i < 9; ++i)
        for (int c = 0; c < 3; ++c) light[i * 3 + std::size_t(c)] = view.sky->radiance_sh[i][c];
    for (int c = 0; c < 3; ++c) light[27 + std::size_t(c)] = view.sun_light->direction[c];
    const bool steady = light == m_last_light;
    m_last_light = light;
    if (light == m_lit_for) return true;
    // Summing every texel of every tile cost 45 ms a frame on `valley`'s tiles (llvmpipe, 2
    // cores) against about 5 ms more shading per fragment: a light that changes every frame (a
    // moving sun) is summed per fragment, and a light that holds still for a frame is summed once.
    if (!steady) return false;
    m_lit_for = light;
    ++m_relights;
    glUseProgram(context.programs->screen(screen_program::shell_relight));
    for (std::size_t p = 0; p < m_transfer.size(); ++p) glBindTextureUnit(GLuint(5 + p), m_transfer[p].id());
    if (m_relight_level < -1)  // asked once (the frame does no string work)
        m_relight_level = glGetUniformLocation(context.programs->screen(screen_program::shell_relight), "u_level");
    const GLint level_location = m_relight_level;
    const int levels = std::bit_width(std::uint32_t(m_transfer_texels));
    for (int level = 0; level < levels; ++level) {
        glBindImageTexture(0, m_lit_seen.id(), level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glBindImageTexture(1, m_lit_other.id(), level, GL_TRUE, 0, GL_WRITE_ONLY, GL_R16F);
        glUniform1i(level_location, level);
        const GLuint groups = (GLuint(std::max(m_transfer_texels >> level, 1)) + 7) / 8;
        glDispatchCompute(groups, groups, GLuint(m_transfer_layers));
        ++context.draw_calls;
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    return true;
}

void shell_pass::draw(pass_context& context) {
    const frame_view& view = *context.view;
    if (!active() || !view.shells || !(view.shells->fade_end_m > 0.0f)) return;
    const shell_view& shells = *view.shells;
    context.timer->begin(gpu_pass::shells);
    // Behrendt 2005 §4: the shells' transfer summed with this frame's light once it holds still.
    const bool relit = !m_transfer.empty() && relight(context);
    context.target->draw_ids(false);
    const GLuint program = context.programs->screen(relit ? screen_program::shell_relit : screen_program::shell);
    uniform_locations& u = m_uniforms[relit ? 1 : 0];
    if (u.program != program) u = uniforms_of(program);
    glUseProgram(program);
    glBindVertexArray(m_vertex_array.id());
    glBindTextureUnit(2, m_colour.id());
    if (m_normal) glBindTextureUnit(3, m_normal.id());
    glBindTextureUnit(4, m_index.id());
    if (relit) {
        glBindTextureUnit(5, m_lit_seen.id());
        glBindTextureUnit(6, m_lit_other.id());
    } else {
        for (std::size_t p = 0; p < m_transfer.size(); ++p) glBindTextureUnit(GLuint(5 + p), m_transfer[p].id());
    }
    if (context.shadows) glBindTextureUnit(1, context.shadows->texture());
    glUniform3fv(u.terrain_position, 1, &view.terrain_position.x);
    glUniform1f(u.slice_height, m_slice_height);
    glUniform1f(u.slant, shells.slant);
    glUniform1f(u.slant_reach, shells.slant_reach_m);
    glUniform1i(u.premultiplied, m_standard_blending ? 0 : 1);
    glUniform4fv(u.lattice, 1, &m_lattice.x);
    glUniform4fv(u.area, 1, &m_area.x);
    glUniform1i(u.layers_per_tile, GLint(m_layers_per_tile));
    glUniform2f(u.fade, shells.fade_start_m, shells.fade_end_m);
    glUniform1i(u.max_level, GLint(levels() - 1));
    glUniform3f(u.level_criterion, shells.pixels_per_radian, k_shell_min_spacing_px, k_shell_merge_band);
    glUniform1iv(u.level_slices, GLsizei(levels()), m_level_slices.data());
    glUniform1iv(u.level_first_layer, GLsizei(levels()), m_level_first_layer.data());
    // Into the half-size layer the colour is fetched at a frame pixel's footprint, half a layer
    // texel's (shaders/shell.frag u_footprint_scale).
    glUniform1f(u.footprint_scale, shells.half_resolution ? 0.5f : 1.0f);
    const glm::vec3 eye = -view.terrain_position;  // terrain-local
    if (shells.half_resolution) begin_layer(context);
    glUseProgram(program);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    // Behrendt 2005 §3.3: c + F·(1 − α); measured against the standard c·α + F·(1 − α).
    if (m_standard_blending)
        glBlendFunci(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    else
        glBlendFunci(0, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    if (shells.half_resolution) {
        glBlendEquationi(1, GL_MIN);  // the layer's nearest slice depth
        glBlendFunci(1, GL_ONE, GL_ONE);
    }
    for (std::size_t t = 0; t < m_tile_ranges.size() && t < view.shell_tile_count; ++t) {
        const shell_tile& tile = view.shell_tiles[t];
        // Outside the view, or wholly nearer than the fade (every fragment would be discarded).
        if (!tile.visible || m_tile_ranges[t].empty()) continue;
        if (glm::length(tile.centre - eye) + tile.radius < shells.fade_start_m) continue;
        // The tile's level: its triangles merge further by their own distance (shaders/shell.vert).
        const std::uint32_t l = std::min<std::uint32_t>(tile.level.level, levels() - 1);
        glUniform1i(u.level, GLint(l));
        const auto& [first, count] = m_tile_ranges[t][std::min<std::size_t>(tile.grid, m_tile_ranges[t].size() - 1)];
        glDrawArraysInstanced(GL_TRIANGLES, GLint(first), GLsizei(count), GLsizei(m_level_slices[l]));
        ++context.draw_calls;
    }
    if (shells.half_resolution) {
        glBlendEquationi(1, GL_FUNC_ADD);
        glBlendFunci(0, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        // The layer over the frame (premultiplied, the same equation), cut by the frame's depth.
        context.target->bind();
        context.target->draw_ids(false);
        glUseProgram(context.programs->screen(screen_program::shell_composite));
        glBindTextureUnit(0, m_layer->color());
        glBindTextureUnit(1, m_layer->nearest_depth());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        ++context.draw_calls;
        if (context.target->has_id_buffer()) {
            // The shells' ID where the layer covers half a pixel or more (k_shell_id), colour kept.
            glDisable(GL_BLEND);
            context.target->draw_ids(true);
            glColorMaski(0, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glUseProgram(context.programs->screen(screen_program::shell_composite_ids));
            glDrawArrays(GL_TRIANGLES, 0, 3);
            ++context.draw_calls;
            glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            context.target->draw_ids(false);
        }
    }
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    context.timer->end();
}

void shell_pass::begin_layer(pass_context& context) {
    const int width = context.target->width(), height = context.target->height();
    if (!m_layer || m_layer->width() != (width + 1) / 2 || m_layer->height() != (height + 1) / 2)
        m_layer.emplace(width, height, false, false);
    m_layer->begin();
    // Its depth: the farthest of each 2x2 of the frame's (shaders/shell_layer_depth.frag).
    glUseProgram(context.programs->screen(screen_program::shell_layer_depth));
    glBindTextureUnit(0, context.target->depth_texture());
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_ALWAYS);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++context.draw_calls;
    glDepthFunc(GL_LEQUAL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    m_layer->draw_blend();  // the slices write colour and their nearest depth
}

}  // namespace sylva::render
