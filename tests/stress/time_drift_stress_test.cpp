// Stress: a million (and ten million) frames of playback. Time is derived from the frame index
// (resources/playback.h), so the clock, the camera path and the sun path at frame N are exactly
// what direct evaluation at N / fps gives; nothing accumulates.
#include <gtest/gtest.h>

#include "app/stress/stress_checks.h"
#include "scenarios/camera_path.h"
#include "stress_support.h"
#include "resources/playback.h"
#include "systems/update_sun_system.h"

namespace sylva {
namespace {

TEST(time_drift_stress, clock_camera_and_sun_do_not_drift_over_ten_million_frames) {
    const auto rows = check_time_drift(2);
    ASSERT_EQ(rows.size(), 5u);
    testing::expect_all_pass(rows);
    EXPECT_EQ(testing::row_named(rows, "clock stepped").value, 0.0);
}

TEST(time_drift_stress, hand_checked_times_at_a_million_frames) {
    // 1e6 / 24 = 41666.666... s; the nearest double is 41666.666666666664.
    EXPECT_EQ((playback_clock{1'000'000, 24.0}.time_s()), 41666.666666666664);
    EXPECT_EQ((playback_clock{10'000'000, 24.0}.time_s()), 10'000'000 / 24.0);
    // Summing 1/24 a million times does drift: that is why the clock never accumulates.
    double sum = 0.0;
    for (int f = 0; f < 1'000'000; ++f) sum += 1.0 / 24.0;
    EXPECT_NE(sum, 1'000'000 / 24.0);
    // A sun key pair 1e6 s apart: at 500,000 s the elevation is exactly halfway.
    sun_track track;
    track.keys = {{0.0, 0.0f, 90.0f}, {1e6, 80.0f, 270.0f}};
    EXPECT_FLOAT_EQ(sample_sun_track(track, 5e5).elevation_deg, 40.0f);
    EXPECT_FLOAT_EQ(sample_sun_track(track, 5e7).elevation_deg, 80.0f);  // holds past the end
}

}  // namespace
}  // namespace sylva
