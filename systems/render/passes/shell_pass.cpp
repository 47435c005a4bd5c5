#include "systems/render/passes/shell_pass.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "lod/shell_blending.h"
#include "models/terrain/wang_tiles.h"
#include "systems/render/renderer.h"
#include "systems/render/textures.h"

namespace sylva::render {
namespace {

struct shell_vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 centre;
};
static_assert(sizeof(shell_vertex) == 36);

}  // namespace

shell_pass::uniform_locations shell_pass::uniforms_of(GLuint program) {
    uniform_locations u;
    u.program = program;
    u.terrain_position = glGetUniformLocation(program, "u_terrain_position");
    u.slice_height = glGetUniformLocation(program, "u_slice_height");
    u.slant = glGetUniformLocation(program, "u_slant");
    u.lattice = glGetUniformLocation(program, "u_lattice");
    u.area = glGetUniformLocation(program, "u_area");
    u.layers_per_tile = glGetUniformLocation(program, "u_layers_per_tile");
    u.fade = glGetUniformLocation(program, "u_fade");
    u.level = glGetUniformLocation(program, "u_level");
    u.merge = glGetUniformLocation(program, "u_merge");
    u.slices_at_level = glGetUniformLocation(program, "u_slices_at_level");
    u.level_first_layer = glGetUniformLocation(program, "u_level_first_layer");
    return u;
}

shell_pass::shell_pass(const scene_assets& assets) {
    const shell_textures& shells = assets.shells;
    if (shells.empty()) return;
    m_slices = std::uint32_t(shells.tiles.front().colour.size());
    m_slice_height = shells.tiles.front().slice_height_m;
    // Level L holds ⌈S / 2^L⌉ slices, each pair of the level below merged (lod/shell_blending.h).
    for (std::uint32_t level = 0; level < shell_pyramid_levels(m_slices); ++level) {
        m_level_first_layer.push_back(m_layers_per_tile);
        m_level_slices.push_back(shell_slices_at_level(m_slices, level));
        m_layers_per_tile += m_level_slices.back();
    }
    std::vector<image_rgba8> colour;
    std::vector<image_rgba8> normal;
    for (const shell_stack& stack : shells.tiles) {
        std::vector<image_rgba8> c = stack.colour;
        std::vector<image_rgba8> n = stack.normal;
        for (;;) {
            colour.insert(colour.end(), c.begin(), c.end());
            normal.insert(normal.end(), n.begin(), n.end());
            if (c.size() == 1) break;
            c = next_pyramid_level(c);
            n = next_normal_pyramid_level(n);
        }
    }
    m_colour = make_texture_array(colour, false);
    m_normal = make_texture_array(normal, false);
    for (const image_rgba8& i : colour) m_uploaded_bytes += 2 * i.texels.size() * 4 / 3;  // both, with mips
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
    // The terrain's triangles, each vertex with its triangle's centre (Eq. 2 needs m).
    std::vector<shell_vertex> vertices;
    for (std::uint16_t id : assets.terrain_meshes) {
        const mesh_data& tile = assets.meshes.at(id);
        const auto first = std::uint32_t(vertices.size());
        for (std::size_t k = 0; k + 2 < tile.indices.size(); k += 3) {
            const vertex* v[3] = {&tile.vertices[tile.indices[k]], &tile.vertices[tile.indices[k + 1]],
                                  &tile.vertices[tile.indices[k + 2]]};
            const glm::vec3 centre = (v[0]->position + v[1]->position + v[2]->position) / 3.0f;
            for (const vertex* p : v) vertices.push_back({p->position, p->normal, centre});
        }
        m_tile_ranges.emplace_back(first, std::uint32_t(vertices.size()) - first);
    }
    m_vertices = make_buffer();
    glNamedBufferStorage(m_vertices.id(), GLsizeiptr(vertices.size() * sizeof(shell_vertex)), vertices.data(), 0);
    m_uploaded_bytes += vertices.size() * sizeof(shell_vertex);
    m_vertex_array = make_vertex_array();
    const GLuint vao = m_vertex_array.id();
    glVertexArrayVertexBuffer(vao, 0, m_vertices.id(), 0, sizeof(shell_vertex));
    for (GLuint a = 0; a < 3; ++a) {
        glVertexArrayAttribFormat(vao, a, 3, GL_FLOAT, GL_FALSE, a * 12);
        glVertexArrayAttribBinding(vao, a, 0);
        glEnableVertexArrayAttrib(vao, a);
    }
}

void shell_pass::draw(pass_context& context) {
    const frame_view& view = *context.view;
    if (!active() || !view.shells || !(view.shells->fade_end_m > 0.0f)) return;
    const shell_view& shells = *view.shells;
    context.timer->begin(gpu_pass::shells);
    context.target->draw_ids(false);
    const GLuint program = context.programs->screen(screen_program::shell);
    if (m_uniforms.program != program) m_uniforms = uniforms_of(program);
    const uniform_locations& u = m_uniforms;
    glUseProgram(program);
    glBindVertexArray(m_vertex_array.id());
    glBindTextureUnit(2, m_colour.id());
    glBindTextureUnit(3, m_normal.id());
    glBindTextureUnit(4, m_index.id());
    if (context.shadows) glBindTextureUnit(1, context.shadows->texture());
    glUniform3fv(u.terrain_position, 1, &view.terrain_position.x);
    glUniform1f(u.slice_height, m_slice_height);
    glUniform1f(u.slant, shells.slant);
    glUniform4fv(u.lattice, 1, &m_lattice.x);
    glUniform4fv(u.area, 1, &m_area.x);
    glUniform1i(u.layers_per_tile, GLint(m_layers_per_tile));
    glUniform2f(u.fade, shells.fade_start_m, shells.fade_end_m);
    const glm::vec3 eye = -view.terrain_position;  // terrain-local
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // Behrendt 2005 §3.3: c + F·(1 − α)
    for (std::size_t t = 0; t < m_tile_ranges.size() && t < view.shell_tile_count; ++t) {
        const shell_tile& tile = view.shell_tiles[t];
        // Wholly nearer than the fade: every fragment would be discarded.
        if (glm::length(tile.centre - eye) + tile.radius < shells.fade_start_m) continue;
        const shell_level level = tile.level;
        const std::uint32_t l = std::min<std::uint32_t>(level.level, levels() - 1);
        glUniform1i(u.level, GLint(l));
        glUniform1f(u.merge, l + 1 < levels() ? level.merge : 0.0f);
        glUniform1i(u.slices_at_level, GLint(m_level_slices[l]));
        glUniform1i(u.level_first_layer, GLint(m_level_first_layer[l]));
        glDrawArraysInstanced(GL_TRIANGLES, GLint(m_tile_ranges[t].first), GLsizei(m_tile_ranges[t].second),
                              GLsizei(m_level_slices[l]));
        ++context.draw_calls;
    }
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    context.timer->end();
}

}  // namespace sylva::render
