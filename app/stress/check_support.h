#pragma once
// What the stress checks (app/stress/*_checks.cpp) share: building a row, the tiny scenario
// they render, and the image statistics two families judge a render by. Internal to the
// suite; tests read rows through app/stress/stress_checks.h.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "app/scenario_player.h"
#include "app/stress/stress_checks.h"
#include "models/image/image.h"
#include "scenarios/scenario.h"

namespace sylva::stress {

using rows = std::vector<stress_row>;

// printf into a string; every measured and limit text is one short line.
template <class... Args>
std::string text(const char* format, Args... args) {
    char buffer[256];
    std::snprintf(buffer, sizeof(buffer), format, args...);
    return buffer;
}

stress_row row(std::string check, std::string measured, double value, std::string limit, bool passed,
               std::string detail = {});

// A row whose measurement is yes or no: value 1 when `ok`, else 0.
stress_row yes_no_row(std::string check, bool ok, std::string measured_if_ok, std::string measured_if_not,
                      std::string limit, std::string detail = {});

// What `attempt` threw as `error` (empty when it returned). Any other exception passes through,
// so the suite reports it as a check that threw.
template <class error = std::exception, class F>
std::string error_from(F&& attempt) {
    try {
        attempt();
    } catch (const error& e) {
        return e.what();
    }
    return {};
}

// The embedded scenarios/tiny.json (k_stress_scenario), drawn by its mesh levels.
scenario tiny_scenario();

// Plays frames 0 and 1 (the first frame has no previous LOD state) and captures frame 1.
image_rgba8 render_frames(scenario_player& player);

struct image_stats {
    double mean = 0.0;       // of R, G, B, 0..255
    double dark = 0.0;       // share of pixels with every channel <= 2
    double saturated = 0.0;  // share of pixels with every channel >= 250
};

image_stats stats_of(const image_rgba8& image);

}  // namespace sylva::stress
