#pragma once
// Billboard-cloud quads (models/bake/billboard_cloud.h, Behrendt 2005 §2.3) of every lighting
// variant, into the shadow cascades and the view.
#include "systems/render/passes/pass_context.h"

namespace sylva::render {

class cloud_draw final : public surface_draw {
public:
    void draw(pass_context& context, const draw_target& target) const override;
};

}  // namespace sylva::render
