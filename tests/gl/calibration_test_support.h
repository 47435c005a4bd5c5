#pragma once
// Settings for a calibration test that runs in a second or two: small counts, three
// repetitions, and the test's own frame timer (a made-up device, or one that reports noise).
#include "systems/render/primitive_cost_calibration.h"

namespace sylva::testing {

inline render::calibration_settings quick_calibration(render::frame_timer timer) {
    render::calibration_settings s;
    s.first_count = 2000;
    s.max_count = 8000;
    s.min_marginal_ms = 1.0;
    s.min_repetitions = 3;
    s.max_repetitions = 3;
    s.timer = std::move(timer);
    return s;
}

}  // namespace sylva::testing
