#pragma once
// The sky drawn behind everything (shaders/sky.frag): the sky's radiance on an equirectangular
// grid, as a float texture. The grid is remade only when what it shows changes (the sun moved,
// the environment map turned), into the same texture and the same CPU buffer, so the frame loop
// neither allocates nor creates GL objects for it.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "components/environment.h"
#include "components/sun.h"
#include "lighting/sky_model.h"
#include "resources/scene_assets.h"
#include "systems/render/gl_objects.h"

namespace sylva::render {

class sky_texture {
public:
    static constexpr int k_width = 128;
    static constexpr int k_height = 64;

    explicit sky_texture(const scene_assets& assets);
    // Brings the texture up to this frame's sky; returns the bytes uploaded (0 when unchanged).
    std::uint64_t update(const environment& sky, const sun& sun_light);
    GLuint id() const { return m_texture.id(); }

private:
    std::uint64_t upload();

    gl_texture m_texture;
    std::vector<float> m_grid;             // CPU radiance grid, k_width x k_height rgb, reused
    std::optional<sky_model> m_sky_drawn;  // what m_texture holds
    // The scene's environment map at the sky texture's size, when it has one: the sky is then
    // this map turned about the vertical, not the analytic sky.
    std::vector<float> m_map;
    std::optional<std::pair<float, float>> m_map_drawn;  // (turn_deg, sky_intensity) drawn
};

}  // namespace sylva::render
