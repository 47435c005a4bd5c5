#pragma once
// The frame's draw list: what build_draw_list produces and the GL submission consumes. Plain
// memory only; the renderer copies `instances` into its persistent mapped ring and turns each
// batch into one indirect draw per sub-mesh.
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "components/lod_state.h"
#include "components/population_ambient.h"
#include "resources/sort_key.h"

namespace sylva {

// draw_item::instance of a plant's partner representation during a transition (fade_alpha): the
// plant's dense index with this bit set. Tile items use the bit above (k_tile_item_bit).
inline constexpr std::uint32_t k_partner_item_bit = 0x40000000u;

// An eco-tile point set's instance record (Deussen 2002 §6.2) adds this to its texture layer:
// the layer still rounds to the species' (GL rounds array layers to the nearest), and
// shaders/transfer.glsl reads the fraction as "samples of many plants, no one plant's sphere".
inline constexpr float k_aggregated_layer_flag = 0.25f;

struct draw_item {
    std::uint64_t key = 0;
    std::uint32_t instance = 0;  // dense index of the plant in its component tables
    // Primitives to draw from the start of the mesh (a point/line prefix, Deussen 2002 §5.3);
    // 0 draws the whole mesh.
    std::uint32_t count = 0;
};
static_assert(sizeof(draw_item) == 16);

// Per-instance data as the vertex shader reads it (instanced attributes, locations 3, 4 and 10).
// Mirrored in shaders/common.glsl; keep both in sync.
struct instance_gpu {
    glm::vec3 position{0.0f};  // camera-relative, metres
    float yaw = 0.0f;
    float scale = 1.0f;
    float tint = 0.0f;           // -1..1 colour variation
    // Fade alpha (transitions). For a points mesh: the prefix's fractional length, ⌈p⌉ less the
    // last splat's point_prefix::last_fade (soft splats draw splat j at clamp(fade − j, 0, 1));
    // build_draw_list writes it, and anyone else drawing points must set it to at least the count.
    float fade = 1.0f;
    float texture_layer = 0.0f;  // layer of the species' textures in the texture arrays
    // Luft 2007 §5: the neighbours' darkening of an implicit-lit plant (components/
    // population_ambient.h); the default darkens nothing.
    population_ambient population;
};
static_assert(sizeof(instance_gpu) == 40);

struct draw_batch {
    render_pass pass = render_pass::opaque;
    std::uint16_t mesh = 0;
    std::uint32_t first_instance = 0;
    std::uint32_t instance_count = 0;
    std::uint32_t count = 0;  // primitives per instance from the mesh's start; 0: all of them
    bool faded = false;       // a transition's partner dissolving by the screen door (sort_key.h)
};

struct draw_list {
    std::vector<draw_item> items;    // sorted by key
    std::vector<draw_item> scratch;  // radix sort ping-pong buffer
    std::vector<instance_gpu> instances;
    // Rebollo 2006: one record per LoDF slot (resources/lodf_slots.h), in slot order, for the
    // foliage its indirect commands draw (instance `slot`, systems/render/lodf_commands.h); a
    // free slot's record is scale 0. Empty when no ladder reaches LoDF.
    std::vector<instance_gpu> lodf_instances;
    std::vector<std::uint32_t> lodf_plants;  // by slot: the plant's dense index, k_no_draw_item when free
    // By slot: the passes its foliage is drawn in (bit render_pass), like an item's: the view
    // when visible, the cascades it overlaps when it is the plant's primary rung.
    std::vector<std::uint32_t> lodf_pass_masks;
    std::vector<draw_batch> batches;
    std::vector<std::uint32_t> chunk_offsets;  // build scratch: items per chunk, prefix-summed
    std::vector<std::uint32_t> chunk_point_plants;  // build scratch: plants drawn as prefixes
    std::vector<std::uint32_t> chunk_eco_plants;    // build scratch: seen plants drawn by their tile
    std::vector<std::uint32_t> chunk_shell_plants;  // build scratch: seen plants drawn by the shells
    // Statistics of the opaque pass (what the viewer sees), for metrics.
    std::array<std::uint32_t, static_cast<std::size_t>(representation::count)> instances_by_representation{};
    std::uint64_t triangles = 0;  // LoDF foliage's included
    std::uint64_t shadow_triangles = 0;
    std::uint64_t points = 0;
    std::uint64_t lines = 0;
};

// Stable LSD radix sort of items by key, 8 bits per pass, skipping byte positions where every
// key agrees (most of the key is usually constant). `scratch` is resized as needed.
struct species_library;

// Groups sorted items into batches (runs of equal pass, mesh and count) and fills the
// statistics (primitives by the mesh's kind; instances of whole meshes by representation).
void build_batches(draw_list& list, const species_library& library);

void radix_sort_draw_items(std::vector<draw_item>& items, std::vector<draw_item>& scratch);

inline constexpr std::uint32_t k_no_draw_item = 0xffffffffu;
// The ID the shells write where their layer covers at least half a pixel (passes/shell_pass.h):
// no instance's (instance_of_id gives k_no_draw_item), but a plant pixel to the coverage metric.
inline constexpr std::uint32_t k_shell_id = 0xffffffffu;

// What a value of the renderer's ID buffer names: the instance records are the LoDF slots'
// (lodf_instances) and then the items', so ID − 1 is a slot, then an item; the terrain's record
// follows them. Returns the draw item's `instance` (a plant's dense index with its partner or
// tile bits), a slot's plant, or k_no_draw_item for 0, a free slot, the terrain and the shells.
inline std::uint32_t instance_of_id(std::uint32_t id, const draw_list& list) {
    if (id == 0) return k_no_draw_item;
    const std::size_t i = id - 1, slots = list.lodf_plants.size();
    if (i < slots) return list.lodf_plants[i];
    return i - slots < list.items.size() ? list.items[i - slots].instance : k_no_draw_item;
}

}  // namespace sylva
