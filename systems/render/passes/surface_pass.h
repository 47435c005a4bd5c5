#pragma once
// The two passes that draw every representation's surfaces: the shadow cascades (depth from
// the sun, Deussen 2002 §6.4's cascades) and the view's opaque pass. Each asks every
// surface_draw in the renderer's order, which is also the order fragments of equal depth
// resolve in: meshes, billboard clouds, then samples.
#include <span>

#include "systems/render/passes/pass_context.h"

namespace sylva::render {

class shadow_cascade_pass final : public frame_pass {
public:
    explicit shadow_cascade_pass(std::span<const surface_draw* const> draws) : m_draws(draws) {}
    void draw(pass_context& context) override;

private:
    std::span<const surface_draw* const> m_draws;
};

class opaque_pass final : public frame_pass {
public:
    explicit opaque_pass(std::span<const surface_draw* const> draws) : m_draws(draws) {}
    void draw(pass_context& context) override;

private:
    std::span<const surface_draw* const> m_draws;
};

}  // namespace sylva::render
