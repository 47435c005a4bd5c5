#pragma once
// The frame's indirect draw commands (glMultiDrawElementsIndirect, GL 4.3 §10.4), grouped by
// pass (each shadow cascade, the view) and by what selects a program (material, primitive,
// lighting variant): each group is one multi-draw. Written straight into the frame ring in two
// sweeps over the draw list -- count per group, then write at each group's place -- so the
// frame loop keeps no per-group vectors and allocates nothing.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "lighting/shadow_cascades.h"
#include "lod/ground_grid.h"
#include "models/mesh.h"
#include "resources/draw_list.h"
#include "resources/scene_assets.h"
#include "resources/sort_key.h"
#include "systems/render/frame_ring.h"
#include "systems/render/mesh_pool.h"

namespace sylva::render {

struct frame_view;

struct command_range {
    std::size_t offset = 0;  // bytes into the ring buffer
    std::uint32_t count = 0;
};

// material_kind: bark, leaf, ground, billboard, billboard_cloud; primitive_kind: triangles,
// points, lines; and whether the draws are a transition's partner dissolving by the screen door
// (draw_batch::faded), which another program draws (program_table pass_kind::view_faded).
inline constexpr std::size_t k_material_kinds = 6;
inline constexpr std::size_t k_primitive_kinds = 3;
inline constexpr std::size_t k_groups_per_pass =
    2 * k_material_kinds * k_primitive_kinds * k_lighting_variants;
using pass_commands = std::array<command_range, k_groups_per_pass>;

constexpr std::size_t group_of(material_kind m, primitive_kind p,
                               lighting_variant l = lighting_variant::normal_mapped, bool faded = false) {
    return ((std::size_t(faded) * k_lighting_variants + std::size_t(l)) * k_primitive_kinds + std::size_t(p)) *
               k_material_kinds +
           std::size_t(m);
}

// A tile of the terrain mesh, drawn where its bounding sphere meets the view (it casts no shadow
// into the cascades: resources/terrain_shadow.h), on
// the grid its ground_tile entity chose this frame (components/ground_tile.h; grid 0 without
// one), with its skirts on that grid where a neighbour's grid differs.
struct terrain_tile {
    glm::vec3 center{0.0f};  // terrain-local
    float radius = 0.0f;
    std::array<std::uint16_t, k_max_ground_grids> grids{};  // mesh ids by grid
    std::array<std::uint16_t, k_max_ground_grids>
        skirts{};  // by grid; scene_assets::k_no_skirt: none
    std::uint8_t grid_count = 1;
    std::array<std::int32_t, 4> neighbours{-1, -1, -1,
                                           -1};  // tile indices sharing an edge; -1: none
};

class draw_commands {
public:
    explicit draw_commands(std::vector<terrain_tile> terrain_tiles);

    // Ring bytes write() may need for `draws` (call before frame_ring::begin_frame).
    std::size_t bytes_needed(const draw_list& draws) const;
    // Groups the draw list's batches and the visible terrain tiles into the ring; returns the
    // bytes written. Shadow batches of cascades past `cascade_count` are dropped.
    // `instance_base`: records before the draw list's (the LoDF slots'), so batch instances and
    // the terrain's are that many further on.
    std::uint64_t write(const frame_view& view, const mesh_pool& meshes, int cascade_count,
                        frame_ring& ring, std::uint32_t instance_base = 0);

    const pass_commands& pass(render_pass p) const { return m_commands[std::size_t(p)]; }
    std::uint32_t command_count() const { return m_command_count; }

private:
    // glMultiDrawElementsIndirect's command layout (GL 4.3 §10.4).
    struct indirect_command {
        std::uint32_t count;
        std::uint32_t instance_count;
        std::uint32_t first_index;
        std::int32_t base_vertex;
        std::uint32_t base_instance;
    };
    static_assert(sizeof(indirect_command) == 20);
    static constexpr std::size_t k_passes = std::size_t(render_pass::count);
    static constexpr std::size_t k_groups = k_passes * k_groups_per_pass;

    // Calls emit(group, command) for every command of the frame, in draw-list order.
    template <typename Emit>
    void for_each_command(const frame_view& view, const mesh_pool& meshes, int cascade_count,
                          std::uint32_t instance_base, Emit&& emit) const;

    std::vector<terrain_tile> m_terrain_tiles;
    std::array<pass_commands, k_passes> m_commands{};
    std::array<std::uint32_t, k_groups> m_written{};  // per group, this sweep
    std::uint32_t m_command_count = 0;
};

}  // namespace sylva::render
