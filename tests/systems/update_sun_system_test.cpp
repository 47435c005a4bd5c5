#include "systems/update_sun_system.h"

#include <gtest/gtest.h>

namespace sylva {
namespace {

TEST(sun_track, interpolates_linearly_and_clamps_at_the_ends) {
    sun_track track;
    track.keys = {{0.0, 10.0f, 100.0f}, {2.0, 30.0f, 140.0f}};
    EXPECT_FLOAT_EQ(sample_sun_track(track, -1.0).elevation_deg, 10.0f);
    EXPECT_FLOAT_EQ(sample_sun_track(track, 1.0).elevation_deg, 20.0f);
    EXPECT_FLOAT_EQ(sample_sun_track(track, 1.5).azimuth_deg, 130.0f);
    EXPECT_FLOAT_EQ(sample_sun_track(track, 5.0).azimuth_deg, 140.0f);
}

TEST(playback_clock, time_is_derived_from_the_frame_without_drift) {
    playback_clock clock{0, 24.0};
    clock.frame = 1'000'000;
    EXPECT_EQ(clock.time_s(), 1'000'000.0 / 24.0);
}

}  // namespace
}  // namespace sylva
