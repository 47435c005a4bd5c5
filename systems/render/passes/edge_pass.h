#pragma once
// The line style's edges (render.style "lines", shaders/edges.frag; Luft 2007 §4, Figure 7): one
// full-screen pass over the finished frame that reads the normal buffer and the depth the
// opaque surfaces wrote and blends ink where either jumps. Nothing without a normal buffer.
#include "systems/render/passes/pass_context.h"

namespace sylva::render {

class edge_pass final : public frame_pass {
public:
    void draw(pass_context& context) override;
};

}  // namespace sylva::render
