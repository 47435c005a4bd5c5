#include "systems/render/sky_texture.h"

#include <cmath>
#include <cstring>
#include <numbers>

#include "lighting/environment_map.h"
#include "systems/project_environment_system.h"
#include "systems/render/textures.h"

namespace sylva::render {
namespace {

constexpr int k_sky_width = sky_texture::k_width;
constexpr int k_sky_height = sky_texture::k_height;

// The sky's radiance on an equirectangular grid, matching the lookup in shaders/sky.frag.
void fill_sky_radiance_grid(const sky_model& sky, std::vector<float>& rgb) {
    rgb.resize(std::size_t(k_sky_width) * k_sky_height * 3);
    for (int j = 0; j < k_sky_height; ++j) {
        const float theta = (float(j) + 0.5f) / k_sky_height * std::numbers::pi_v<float>;
        for (int i = 0; i < k_sky_width; ++i) {
            const float phi =
                ((float(i) + 0.5f) / k_sky_width - 0.5f) * 2.0f * std::numbers::pi_v<float>;
            glm::vec3 d{std::sin(theta) * std::sin(phi), std::cos(theta),
                        -std::sin(theta) * std::cos(phi)};
            glm::vec3 l = sky.radiance(d);
            std::memcpy(&rgb[(std::size_t(j) * k_sky_width + i) * 3], &l, sizeof(l));
        }
    }
}

// The environment map (k_sky_width x k_sky_height, rows from the zenith) turned by turn_deg
// of azimuth about the vertical: world column i shows the map at azimuth phi_i - turn, read
// with linear interpolation across columns (wrapping at south), scaled by `intensity`.
void fill_map_sky_grid(const std::vector<float>& map, float turn_deg, float intensity,
                       std::vector<float>& rgb) {
    rgb.resize(std::size_t(k_sky_width) * k_sky_height * 3);
    // A non-finite turn (no scenario gives one) draws the map unturned, as the SH are.
    const double shift = std::isfinite(turn_deg) ? double(turn_deg) / 360.0 * k_sky_width : 0.0;
    for (int i = 0; i < k_sky_width; ++i) {
        double source = std::fmod(double(i) - shift, double(k_sky_width));
        if (source < 0.0) source += k_sky_width;
        const auto left = int(source) % k_sky_width;
        const int right = (left + 1) % k_sky_width;
        const auto t = float(source - std::floor(source));
        for (int j = 0; j < k_sky_height; ++j) {
            const std::size_t row = std::size_t(j) * k_sky_width;
            for (int c = 0; c < 3; ++c) {
                const float a = map[(row + std::size_t(left)) * 3 + std::size_t(c)];
                const float b = map[(row + std::size_t(right)) * 3 + std::size_t(c)];
                rgb[(row + std::size_t(i)) * 3 + std::size_t(c)] = intensity * (a + (b - a) * t);
            }
        }
    }
}

bool same_sky(const sky_model& a, const sky_model& b) {
    return a.sun_direction == b.sun_direction && a.turbidity == b.turbidity &&
           a.sky_intensity == b.sky_intensity && a.ground_albedo == b.ground_albedo &&
           a.sun_irradiance == b.sun_irradiance;
}

}  // namespace

sky_texture::sky_texture(const scene_assets& assets)
    : m_grid(std::size_t(k_sky_width) * k_sky_height * 3) {
    if (assets.environment_sky.width > 0)
        m_map = downsample_environment_map(assets.environment_sky, k_sky_width, k_sky_height).rgb;
}

std::uint64_t sky_texture::update(const environment& sky, const sun& sun_light) {
    if (!m_map.empty()) {
        // An environment map: only its turn and brightness change while the scene plays.
        const std::pair key{environment_map_turn_deg(sky, sun_light), sky.sky_intensity};
        if (m_texture && m_map_drawn == key) return 0;
        fill_map_sky_grid(m_map, key.first, key.second > 0.0f ? key.second : 0.0f, m_grid);
        m_map_drawn = key;
        return upload();
    }
    // Keyed on the sky's inputs, not on environment::sky_revision: revisions count changes of
    // one environment, and two environments drawn by one renderer (the primitive-cost
    // calibration's and a scene's) can share a number while their skies differ.
    const sky_model model = analytic_sky(sky, sun_light.direction);
    if (m_texture && m_sky_drawn && same_sky(*m_sky_drawn, model)) return 0;
    fill_sky_radiance_grid(model, m_grid);
    m_sky_drawn = model;
    return upload();
}

std::uint64_t sky_texture::upload() {
    if (!m_texture)
        m_texture = make_float_texture(k_sky_width, k_sky_height, m_grid.data());
    else  // the sun moved: same texture, new texels (no GL allocation in the frame loop)
        glTextureSubImage2D(m_texture.id(), 0, 0, 0, k_sky_width, k_sky_height, GL_RGB, GL_FLOAT,
                            m_grid.data());
    return m_grid.size() * sizeof(float);
}

}  // namespace sylva::render
