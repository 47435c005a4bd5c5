#pragma once
// Whole meshes: the terrain, bark, alpha-tested leaf cards and crossed billboards
// (models/bake/crossed_billboard.h), into the shadow cascades and the view.
#include "systems/render/passes/pass_context.h"

namespace sylva::render {

class mesh_draw final : public surface_draw {
public:
    void draw(pass_context& context, const draw_target& target) const override;

private:
    static void draw_casters(pass_context& context, const draw_target& target);
    static void draw_view(pass_context& context, const draw_target& target);
};

}  // namespace sylva::render
