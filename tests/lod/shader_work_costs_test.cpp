// The fit of what shader work costs (lod/shader_work_costs.h), on hand-built samples.
#include "lod/shader_work_costs.h"

#include <gtest/gtest.h>

namespace sylva {
namespace {

// Three samples as the calibration takes them: 64,000 small triangles in the view (3 vertices
// and about 40 fragments each), as many large ones (about 450 fragments each), and the large
// ones into a shadow map (2,800 texels each), drawn by a device with c_v = 0.2 µs,
// c_f = 0.003 µs and c_s = 0.002 µs:
//   small:  0.2·192,000 + 0.003·2,560,000                = 38,400 +  7,680        =  46,080 µs
//   large:  0.2·192,000 + 0.003·28,800,000               = 38,400 + 86,400        = 124,800 µs
//   shadow: 0.2·192,000 + 0.002·179,200,000              = 38,400 + 358,400       = 396,800 µs
std::vector<work_sample> device_samples() {
    return {{46080.0, 100.0, 192000.0, 2560000.0, 0.0},
            {124800.0, 100.0, 192000.0, 28800000.0, 0.0},
            {396800.0, 100.0, 192000.0, 0.0, 179200000.0}};
}

TEST(shader_work_costs, the_fit_recovers_the_coefficients_of_hand_computed_samples) {
    const shader_work_costs c = fit_shader_work(device_samples());
    EXPECT_NEAR(c.vertex_us, 0.2, 1e-9);
    EXPECT_NEAR(c.fragment_us, 0.003, 1e-12);
    EXPECT_NEAR(c.shadow_fragment_us, 0.002, 1e-12);
    // A rung's cost from its counts: 12,200 vertices, 306,000 fragments, 10,300 shadow
    // vertices and 1.6 M shadow fragments (a full oak at 128 px):
    // 0.2·22,500 + 0.003·306,000 + 0.002·1,600,000 = 4,500 + 918 + 3,200 = 8,618 µs.
    EXPECT_NEAR(c.cost_us(12200.0, 306000.0, 10300.0, 1600000.0), 8618.0, 1e-6);
}

TEST(shader_work_costs, a_fourth_sample_is_fitted_by_least_squares) {
    std::vector<work_sample> s = device_samples();
    s.push_back({0.2 * 96000.0 + 0.003 * 1000000.0 + 0.002 * 5000000.0, 100.0, 96000.0, 1000000.0, 5000000.0});
    const shader_work_costs c = fit_shader_work(s);
    EXPECT_NEAR(c.vertex_us, 0.2, 1e-9);
    EXPECT_NEAR(c.shadow_fragment_us, 0.002, 1e-12);
}

TEST(shader_work_costs, refuses_times_within_the_noise) {
    std::vector<work_sample> s = device_samples();
    s[1].error_us = s[1].us / 4.0;  // only 4 standard errors above zero
    EXPECT_THROW(fit_shader_work(s), work_calibration_refused);
}

TEST(shader_work_costs, refuses_samples_that_cannot_separate_the_work) {
    std::vector<work_sample> s = device_samples();
    s[1] = s[0];  // two small-triangle samples: vertices and fragments move together
    EXPECT_THROW(fit_shader_work(s), work_calibration_refused);
    std::vector<work_sample> no_shadow = device_samples();
    no_shadow.pop_back();
    EXPECT_THROW(fit_shader_work(no_shadow), work_calibration_refused);
}

TEST(shader_work_costs, refuses_a_negative_coefficient) {
    std::vector<work_sample> s = device_samples();
    s[1].us = 40000.0;  // more fragments, less time: the fragment cost comes out negative
    EXPECT_THROW(fit_shader_work(s), work_calibration_refused);
}

}  // namespace
}  // namespace sylva
