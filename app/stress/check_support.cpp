#include "app/stress/check_support.h"

#include <algorithm>
#include <stdexcept>

#include "scenarios/embedded_files.h"
#include "scenarios/scenario_loader.h"

namespace sylva::stress {

stress_row row(std::string check, std::string measured, double value, std::string limit, bool passed,
               std::string detail) {
    return {std::move(check), std::move(measured), value, std::move(limit), passed, std::move(detail)};
}

stress_row yes_no_row(std::string check, bool ok, std::string measured_if_ok, std::string measured_if_not,
                      std::string limit, std::string detail) {
    return row(std::move(check), ok ? std::move(measured_if_ok) : std::move(measured_if_not), ok ? 1.0 : 0.0,
               std::move(limit), ok, std::move(detail));
}

scenario tiny_scenario() {
    const auto json = embedded_file(k_stress_scenario);
    if (!json) throw std::runtime_error(std::string(k_stress_scenario) + " is not embedded");
    scenario s = load_scenario_text(*json, k_stress_scenario);
    // The checks stress the frame loop's numbers (offsets, light, time, LOD distances), not the
    // ladder: they draw tiny's mesh levels, whose switches lod_scale moves, and need no rung
    // tables (an auto ladder measures them first, ~100 s without a bake cache).
    draw_by(s, "mesh_levels");
    return s;
}

image_rgba8 render_frames(scenario_player& player) {
    player.step();
    player.step();
    return player.capture();
}

image_stats stats_of(const image_rgba8& image) {
    image_stats s;
    const std::size_t pixels = std::size_t(image.width) * image.height;
    for (std::size_t p = 0; p < pixels; ++p) {
        const std::uint8_t* t = &image.texels[4 * p];
        s.mean += (double(t[0]) + t[1] + t[2]) / 3.0;
        s.dark += std::max({t[0], t[1], t[2]}) <= 2 ? 1.0 : 0.0;
        s.saturated += std::min({t[0], t[1], t[2]}) >= 250 ? 1.0 : 0.0;
    }
    if (pixels == 0) return s;
    s.mean /= double(pixels);
    s.dark /= double(pixels);
    s.saturated /= double(pixels);
    return s;
}

}  // namespace sylva::stress
