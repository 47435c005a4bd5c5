#include "systems/render/terrain_shadow_texture.h"

#include <algorithm>
#include <cmath>

namespace sylva::render {

std::uint64_t terrain_shadow_texture::update(const terrain_shadow* shadow) {
    m_casts = shadow && shadow->resolution >= 2 && shadow->deepest_m > 0.0f &&
              shadow->texels.size() == std::size_t(shadow->resolution) * shadow->resolution * 2;
    if (!m_casts) return 0;
    if (m_texture && m_resolution == shadow->resolution && m_revision == shadow->revision &&
        m_sun == shadow->sun_direction)
        return 0;
    const auto n = GLsizei(shadow->resolution);
    if (!m_texture || m_resolution != shadow->resolution) {
        m_texture = make_texture(GL_TEXTURE_2D);
        glTextureStorage2D(m_texture.id(), 1, GL_RG32F, n, n);
        glTextureParameteri(m_texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(m_texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTextureParameteri(m_texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(m_texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    glTextureSubImage2D(m_texture.id(), 0, 0, 0, n, n, GL_RG, GL_FLOAT, shadow->texels.data());
    m_resolution = shadow->resolution;
    m_revision = shadow->revision;
    m_sun = shadow->sun_direction;
    // A shadow's edge as wide as the sun's ray climbs over one sample (the sweep's interpolation
    // smooths the edge by about that much), at least 5 cm, at most a sample's spacing.
    const double horizontal = std::hypot(double(m_sun.x), double(m_sun.z));
    const double rise = shadow->spacing() * double(m_sun.y) / std::max(horizontal, 1e-6);
    m_edge_m = float(std::clamp(rise, 0.05, std::max(shadow->spacing(), 0.05)));
    return shadow->texels.size() * sizeof(float);
}

glm::vec4 terrain_map(glm::vec3 terrain_position, std::uint32_t resolution, double size_m) {
    if (resolution < 2) return glm::vec4(0.0f);
    // Sample i of a row sits at x = -size/2 + i spacing from the terrain's origin and at texture
    // coordinate (i + 0.5) / resolution.
    const double spacing = size_m / double(resolution - 1);
    const auto half = float(0.5 * size_m);
    return glm::vec4(half - terrain_position.x, half - terrain_position.z,
                     float(1.0 / (spacing * double(resolution))), float(0.5 / double(resolution)));
}

void terrain_shadow_texture::uniforms(glm::vec3 terrain_position, bool shadows_on,
                                      glm::vec4& params) const {
    if (!m_casts || !shadows_on) {
        params = glm::vec4(0.0f, 1.0f, 0.0f, params.w);
        return;
    }
    params = glm::vec4(-terrain_position.y, m_edge_m, 1.0f, params.w);
}

}  // namespace sylva::render
