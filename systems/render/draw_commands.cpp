#include "systems/render/draw_commands.h"

#include <algorithm>
#include <cstring>

#include "systems/build_draw_list_system.h"
#include "systems/cull_system.h"
#include "systems/render/renderer.h"

namespace sylva::render {
namespace {

constexpr std::uint32_t vertices_per(primitive_kind p) {
    return p == primitive_kind::triangles ? 3u : (p == primitive_kind::lines ? 2u : 1u);
}
static_assert(std::size_t(material_kind::facing_billboard) + 1 == k_material_kinds,
              "k_material_kinds counts material_kind");

}  // namespace

draw_commands::draw_commands(std::vector<terrain_tile> terrain_tiles)
    : m_terrain_tiles(std::move(terrain_tiles)) {}

std::size_t draw_commands::bytes_needed(const draw_list& draws) const {
    // A terrain tile: its surface and skirts in the view.
    return (draws.batches.size() + m_terrain_tiles.size() * 2 + 8) * k_material_kinds *
           sizeof(indirect_command);
}

template <typename Emit>
void draw_commands::for_each_command(const frame_view& view, const mesh_pool& meshes,
                                     int cascade_count, std::uint32_t instance_base, Emit&& emit) const {
    // `primitives` > 0 draws that many primitives from the start of each submesh (a prefix,
    // Deussen 2002 §5.3); 0 draws them all.
    auto add = [&](render_pass pass, const gpu_mesh& mesh, std::uint32_t first, std::uint32_t count,
                   std::uint32_t primitives = 0, bool faded = false) {
        const std::uint32_t per = vertices_per(mesh.primitive);
        for (const auto& sub : mesh.submeshes) {
            const std::uint32_t indices =
                primitives ? std::min(primitives * per, sub.index_count) : sub.index_count;
            emit(std::size_t(pass) * k_groups_per_pass +
                     group_of(sub.material, mesh.primitive, sub.lighting, faded),
                 indirect_command{indices, count, sub.first_index, sub.base_vertex, first});
        }
    };
    const draw_list& draws = *view.draws;
    for (const auto& batch : draws.batches) {
        if (is_shadow_pass(batch.pass) && int(batch.pass) >= cascade_count) continue;
        add(batch.pass, meshes.get(batch.mesh), instance_base + batch.first_instance, batch.instance_count,
            batch.count, batch.faded);
    }
    // Terrain tiles: each one drawn where its bounding sphere meets the view.
    const auto terrain_instance = instance_base + std::uint32_t(draws.instances.size());
    const camera& cam = *view.view_camera;
    const frustum_planes frustum = extract_frustum_planes(cam.projection * cam.view);
    // Each on its ground tile's grid (components/ground_tile.h).
    auto grid_of = [&](std::size_t t) -> std::uint8_t {
        if (t >= view.ground_tile_count) return 0;
        return std::min<std::uint8_t>(view.ground_tiles[t].grid, m_terrain_tiles[t].grid_count - 1);
    };
    for (std::size_t t = 0; t < m_terrain_tiles.size(); ++t) {
        const terrain_tile& tile = m_terrain_tiles[t];
        const std::uint8_t grid = grid_of(t);
        // Skirts where an edge parts from a neighbour's on another grid (terrain_tile_skirts).
        bool skirted = false;
        if (tile.skirts[grid] != scene_assets::k_no_skirt)
            for (std::int32_t n : tile.neighbours)
                skirted = skirted || (n >= 0 && grid_of(std::size_t(n)) != grid);
        const glm::vec3 center = view.terrain_position + tile.center;
        // Not into the cascades: the ground's shadow comes from its heights
        // (lighting/terrain_shadow.h), which shade the ground and everything on it.
        if (!sphere_in_frustum(frustum, center, tile.radius)) continue;
        add(render_pass::opaque, meshes.get(tile.grids[grid]), terrain_instance, 1);
        if (skirted) add(render_pass::opaque, meshes.get(tile.skirts[grid]), terrain_instance, 1);
    }
}

std::uint64_t draw_commands::write(const frame_view& view, const mesh_pool& meshes,
                                   int cascade_count, frame_ring& ring, std::uint32_t instance_base) {
    // Sweep 1: how many commands each group holds.
    m_written.fill(0);
    for_each_command(view, meshes, cascade_count, instance_base,
                     [&](std::size_t group, const indirect_command&) { ++m_written[group]; });
    m_command_count = 0;
    for (std::uint32_t n : m_written) m_command_count += n;
    const std::size_t bytes = std::size_t(m_command_count) * sizeof(indirect_command);
    const frame_ring::allocation block = ring.allocate(std::max<std::size_t>(bytes, 1), 16);
    // Each group's place in the block, groups in (pass, group) order.
    std::size_t offset = 0;
    for (std::size_t g = 0; g < k_groups; ++g) {
        command_range& range = m_commands[g / k_groups_per_pass][g % k_groups_per_pass];
        range = {std::size_t(block.offset) + offset, m_written[g]};
        offset += std::size_t(m_written[g]) * sizeof(indirect_command);
    }
    // Sweep 2: the commands at their group's place, in draw-list order within each group.
    m_written.fill(0);
    auto* base = static_cast<std::byte*>(block.data);
    for_each_command(
        view, meshes, cascade_count, instance_base, [&](std::size_t group, const indirect_command& command) {
            const command_range& range =
                m_commands[group / k_groups_per_pass][group % k_groups_per_pass];
            const std::size_t at = range.offset - std::size_t(block.offset) +
                                   std::size_t(m_written[group]++) * sizeof(indirect_command);
            std::memcpy(base + at, &command, sizeof(command));
        });
    return bytes;
}

}  // namespace sylva::render
