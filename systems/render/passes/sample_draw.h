#pragma once
// The point and line representation's samples (Deussen 2002 §5.1, §5.2) of bark and leaf
// parts: into a shadow cascade, the view's opaque pass (lines, and points unless they are
// soft), or the soft splats' two passes (passes/soft_splat_pass.h).
#include "systems/render/passes/pass_context.h"

namespace sylva::render {

class sample_draw final : public surface_draw {
public:
    void draw(pass_context& context, const draw_target& target) const override;

private:
    static void set_point_uniforms(const pass_context& context, const draw_target& target,
                                   const surface_program& program);
};

}  // namespace sylva::render
