#pragma once
// Soft splats (lod/point_line_lod.h), after the sky so that they blend over it: opaque splats
// pushed back by ε into depth only (and IDs), then the Gaussians, depth-tested against that and
// blended "over" without writing depth. Splats of at least k_splat_layer_min_side_px are drawn
// into the half-size splat layer (splat_layer.h), each keeping the nearest splat depth, and the
// layer is filtered up over the frame at that depth (with an ID buffer, its IDs with it);
// smaller ones straight into the frame. The target's alpha is kept.
#include <optional>
#include <span>

#include "systems/render/passes/pass_context.h"
#include "systems/render/splat_layer.h"

namespace sylva::render {

class soft_splat_pass final : public frame_pass {
public:
    explicit soft_splat_pass(std::span<const surface_draw* const> draws) : m_draws(draws) {}
    void draw(pass_context& context) override;

private:
    void composite(pass_context& context);

    std::span<const surface_draw* const> m_draws;
    std::optional<splat_layer> m_layer;  // made when layered splats are first drawn
};

}  // namespace sylva::render
