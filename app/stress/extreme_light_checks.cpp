// Extreme light (app/stress/stress_checks.h): sky and sun from darkness to 1e12, the sun below,
// on and above the horizon, turbidity at the loader's limits. The sky's SH projection and the
// sun's radiance stay finite and linear; rendered, the scene is black, white or lit as it
// should be, never NaN (which llvmpipe writes as black).
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/trigonometric.hpp>
#include <glm/vector_relational.hpp>
#include <limits>

#include "app/stress/check_support.h"
#include "app/stress/stress_checks.h"
#include "components/environment.h"
#include "components/sun.h"
#include "lighting/sky_model.h"
#include "lighting/spherical_harmonics.h"
#include "systems/update_sun_system.h"

namespace sylva {
namespace {

using stress::row;
using stress::rows;
using stress::text;

bool finite(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finite(const std::array<glm::vec3, 9>& sh) {
    return std::all_of(sh.begin(), sh.end(), [](glm::vec3 c) { return finite(c); });
}

constexpr float k_sun_elevations[] = {-90.0f, -10.0f, 0.0f, 45.0f, 90.0f};
constexpr float k_turbidities[] = {1.7f, 10.0f};  // the scenario loader's range

double max_abs(const sh9_rgb& sh) {
    double m = 0.0;
    for (const glm::vec3 c : sh.c)
        m = std::max({m, double(std::abs(c.x)), double(std::abs(c.y)), double(std::abs(c.z))});
    return m;
}

sh9_rgb irradiance_sh(float sky_intensity, float elevation_deg, float turbidity) {
    sky_model sky;
    sky.sun_direction = sun_direction_from_angles(elevation_deg, 135.0f);
    sky.turbidity = turbidity;
    sky.sky_intensity = sky_intensity;
    return irradiance_from_radiance(project_sky(sky, 32, 64));
}

struct light_case {
    std::string name;
    float sun_intensity = 3.0f;
    float sky_intensity = 1.0f;
    float elevation_deg = 40.0f;
    float turbidity = 3.0f;
    enum class expect { black, white, lit, any } image = expect::any;
};

}  // namespace

rows check_extreme_sky() {
    rows out;
    std::vector<sh9_rgb> unit;  // sky intensity 1, per (elevation, turbidity)
    for (const float e : k_sun_elevations)
        for (const float t : k_turbidities) unit.push_back(irradiance_sh(1.0f, e, t));
    for (const float intensity : {0.0f, 1e-6f, 1.0f, 1e6f, 1e12f}) {
        bool all_finite = true;
        double linear_error = 0.0;
        std::size_t k = 0;
        for (const float e : k_sun_elevations)
            for (const float t : k_turbidities) {
                const sh9_rgb sh = irradiance_sh(intensity, e, t);
                const sh9_rgb& one = unit[k++];
                all_finite = all_finite && finite(sh.c);
                const double scale = std::max(max_abs(one) * double(intensity), 1e-300);
                for (std::size_t i = 0; i < 9; ++i)
                    for (int ch = 0; ch < 3; ++ch)
                        linear_error = std::max(
                            linear_error,
                            std::abs(double(sh.c[i][ch]) - double(one.c[i][ch]) * intensity) /
                                scale);
            }
        // Zero sky must give exactly zero light; otherwise SH(I) = I SH(1) to float rounding.
        const bool ok = all_finite && linear_error < 1e-5;
        out.push_back(row(
            text("sky SH, sky intensity %g", double(intensity)),
            all_finite ? text("finite, rel err %.1e", linear_error) : "NOT finite", linear_error,
            intensity == 0.0f ? "finite, all 0" : "finite, I x SH(1) +- 1e-5", ok,
            text("%zu sun elevations -90..90 x turbidity 1.7, 10", std::size(k_sun_elevations))));
    }
    // The sun's colour times its intensity is what the shader gets (renderer.cpp write_uniforms).
    bool sun_finite = true, dark_below = true;
    float brightest = 0.0f;
    for (const float intensity : {0.0f, 1e-6f, 1e6f, 1e12f})
        for (const float e : k_sun_elevations)
            for (const float t : k_turbidities) {
                const glm::vec3 radiance = sun_radiance_color(glm::radians(e), t) * intensity;
                sun_finite = sun_finite && finite(radiance) &&
                             glm::all(glm::greaterThanEqual(radiance, glm::vec3(0.0f)));
                if (e < -1.0f) dark_below = dark_below && radiance == glm::vec3(0.0f);
                brightest = std::max(brightest, radiance.y);
                sun_finite = sun_finite && finite(sun_direction_from_angles(e, 135.0f));
            }
    out.push_back(row("sun radiance, intensity 0..1e12",
                      text("finite, max %.2g", double(brightest)), double(brightest),
                      "finite, >= 0, 0 below -1 deg", sun_finite && dark_below));
    // Out-of-range inputs through the API (the loader never lets them through): clamped.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    sky_model hazy;
    hazy.turbidity = nan;
    const bool odd_ok = finite(irradiance_sh(1.0f, 45.0f, nan).c) &&
                        finite(hazy.radiance(glm::vec3(0.0f, 1.0f, 0.0f))) &&
                        finite(sun_radiance_color(nan, 3.0f)) &&
                        finite(sun_radiance_color(0.5f, nan));
    out.push_back(stress::yes_no_row("sky and sun, NaN turbidity / elevation", odd_ok, "finite",
                                     "NOT finite", "finite"));
    return out;
}

rows check_extreme_light_renders(render::gl_context& context, int threads) {
    using expect = light_case::expect;
    const light_case cases[] = {
        {"sun 0, sky 0", 0.0f, 0.0f, 40.0f, 3.0f, expect::black},
        {"sun 1e-6, sky 1e-6", 1e-6f, 1e-6f, 40.0f, 3.0f, expect::black},
        {"sun 1e6, sky 1e6", 1e6f, 1e6f, 40.0f, 3.0f, expect::white},
        {"sun 1e12, sky 1e12 (API)", 1e12f, 1e12f, 40.0f, 3.0f, expect::white},
        {"sun below horizon (-90)", 3.0f, 1.0f, -90.0f, 3.0f, expect::any},
        {"sun on the horizon (0)", 3.0f, 1.0f, 0.0f, 3.0f, expect::lit},
        {"sun at the zenith (90)", 3.0f, 1.0f, 90.0f, 3.0f, expect::lit},
        {"turbidity 1.7", 3.0f, 1.0f, 40.0f, 1.7f, expect::lit},
        {"turbidity 10", 3.0f, 1.0f, 40.0f, 10.0f, expect::lit},
    };
    context.make_current();
    const scenario base = stress::tiny_scenario();
    rows out;
    for (const light_case& c : cases) {
        scenario s = base;
        s.sun.keyframes = {{0.0, c.elevation_deg, 135.0f}};
        s.sun.turbidity = c.turbidity;
        scenario_player player(s, threads, &context);
        // Set directly so 1e12 (beyond the loader's 1e6) reaches update_sun and the projection.
        player.world().resource<sun_track>().intensity = c.sun_intensity;
        player.world().single<environment>().sky_intensity = c.sky_intensity;
        const image_rgba8 image = stress::render_frames(player);
        const sun& light = player.world().single<sun>();
        const environment& env = player.world().single<environment>();
        const bool uniforms_finite = finite(light.direction) &&
                                     finite(light.color * light.intensity) &&
                                     finite(env.irradiance_sh);
        const stress::image_stats st = stress::stats_of(image);
        bool image_ok = image.width == base.width && image.height == base.height;
        std::string limit = "SH, sun finite";
        // NaN reaching the framebuffer is written as 0 by llvmpipe, so a saturated scene with
        // black pixels would show it; a lit scene must have (almost) no black pixels.
        switch (c.image) {
            case expect::black:
                image_ok = image_ok && st.dark == 1.0;
                limit += "; all px <= 2";
                break;
            case expect::white:
                image_ok = image_ok && st.saturated > 0.99;
                limit += "; > 99 % px >= 250";
                break;
            case expect::lit:
                image_ok = image_ok && st.dark < 0.01 && st.mean > 10.0;
                limit += "; lit, < 1 % px black";
                break;
            case expect::any:
                break;
        }
        out.push_back(row("render " + c.name,
                          text("%s, mean %.0f, %.0f %% white", uniforms_finite ? "finite" : "NaN",
                               st.mean, 100.0 * st.saturated),
                          st.mean, limit, uniforms_finite && image_ok,
                          text("%.1f %% of pixels black", 100.0 * st.dark)));
    }
    return out;
}

}  // namespace sylva
