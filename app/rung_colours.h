#pragma once
// The view's false-colour mode (issue 21 item 6): every plant pixel tinted by the rung its plant
// is drawn with this frame (lod_state::current, the primary in a band), shaded by the pixel's own
// brightness so the shapes stay readable; sky and terrain keep their colours, dimmed.
#include <array>
#include <span>
#include <string_view>
#include <vector>

#include "components/lod_state.h"
#include "models/image/image.h"

namespace sylva {

struct rung_colour {
    representation rung;
    std::string_view name;
    std::array<std::uint8_t, 3> rgb;
};

// The key, one colour per representation a plant can be drawn with.
inline constexpr std::array<rung_colour, 10> k_rung_colours{{
    {representation::mesh_full, "mesh_full", {230, 60, 50}},
    {representation::mesh_reduced, "mesh_reduced", {240, 150, 40}},
    {representation::mesh_far, "mesh_far", {230, 220, 60}},
    {representation::billboard_cloud, "billboard_cloud", {60, 200, 90}},
    {representation::points, "points_lines", {60, 150, 240}},
    {representation::crossed_billboard, "crossed_billboard", {190, 90, 230}},
    {representation::eco_tile, "eco_tile_points", {60, 220, 220}},
    {representation::lodf, "lodf", {250, 110, 160}},
    {representation::shell, "shell", {150, 150, 150}},  // no plant pixel is ever a shell's
    {representation::facing_billboard, "facing_billboard", {240, 130, 220}},
}};

// `image` with every pixel whose ID (capture_plant_ids: plant index + 1, 0 for none) names a
// plant tinted by that plant's rung in `lods` (the lod_state table, in plant order).
image_rgba8 tint_by_rung(const image_rgba8& image, std::span<const std::uint32_t> ids,
                         std::span<const lod_state> lods);

}  // namespace sylva
