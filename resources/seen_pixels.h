#pragma once
// How much of each plant the last frame showed, for the auto ladder (issue 21 item 3).
//
// The rung tables (app/rung_tables.h) judge a species alone, wholly in view. In a frame most
// plants are not: in `default`'s forest band each tree shows little more than its crown's top
// behind the trees in front, while the ferns at the camera's feet show whole. Judged alone, a
// billboard cloud for each of those trees bought more than full meshes for the near ferns;
// measured in the frame it bought less (SSIM +0.011 for 190 ms against +0.021 for 350 ms).
// So select_representation weighs each plant's error by the share of its pixels the last
// frame showed: the pixels the renderer's instance-ID buffer gave the plant, over the pixels
// its rung covers alone at its size (the tables' drawn pixels). Occlusion culling does the same
// with the all-or-nothing share; this is its graded form, from the frame already drawn.
//
// Written by the submit system after each frame when `wanted` (the auto ladder asks, and the
// renderer then keeps an ID buffer); read by select_representation the next frame. A plant the
// last frame did not draw counts as wholly seen. The ID buffer is drawn like the image, so the
// counts, and the choices they steer, are the same for any thread count.
#include <cstdint>
#include <span>
#include <vector>

#include "resources/draw_list.h"

namespace sylva {

struct seen_pixels {
    bool wanted = false;
    bool measured = false;                // the last frame was counted
    std::vector<std::uint32_t> by_plant;  // pixels, by dense plant index; beyond its end: none
    std::vector<std::uint8_t> in_view;    // 1: the last frame drew the plant in the view
    std::vector<std::uint32_t> ids;       // the ID buffer read back, kept so a frame allocates nothing
    std::uint32_t at(std::size_t plant) const { return plant < by_plant.size() ? by_plant[plant] : 0u; }
    bool drawn(std::size_t plant) const { return plant < in_view.size() && in_view[plant] != 0; }
};

// A plant's pixels in the last frame, or -1 when the last frame did not count or did not draw
// it in the view (then it is judged whole; lod/rung_solver.h shown_last_frame).
inline float shown_pixels(const seen_pixels& seen, std::size_t plant) {
    return seen.measured && seen.drawn(plant) ? float(seen.at(plant)) : -1.0f;
}

// Counts each plant's pixels in `ids` (per pixel, the draw-list item index + 1 the renderer
// wrote, 0 for none; render::renderer::read_ids) into `out`, and marks it measured. A plant's
// partner rung counts as the plant; eco-tile point sets and the terrain count for no plant.
void count_seen_pixels(std::span<const std::uint32_t> ids, const draw_list& draws, seen_pixels& out);

}  // namespace sylva
