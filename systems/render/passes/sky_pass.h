#pragma once
// The sky (shaders/sky.frag), drawn after the opaque surfaces at the far plane: only pixels no
// surface covered are shaded.
#include "systems/render/passes/pass_context.h"
#include "systems/render/sky_texture.h"

namespace sylva::render {

class sky_pass final : public frame_pass {
public:
    explicit sky_pass(const sky_texture& sky) : m_sky(sky) {}
    void draw(pass_context& context) override;

private:
    const sky_texture& m_sky;
};

}  // namespace sylva::render
