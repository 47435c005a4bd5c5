#pragma once
// Resources that drive a frame: the clock and the scripted camera and sun paths. Written by the
// player (clock) and by scenario spawning (tracks); read by update_camera and update_sun.
#include <cstdint>
#include <vector>

#include "scenarios/camera_path.h"

namespace sylva {

// Time is derived from the frame number, never accumulated, so a million frames of playback
// land on exactly frame / fps (no floating-point drift).
struct playback_clock {
    std::uint64_t frame = 0;
    double fps = 24.0;
    double time_s() const { return double(frame) / fps; }
};

struct camera_track {
    std::vector<camera_keyframe> keys;  // absolute world positions (terrain heights resolved)
    bool follow = true;                 // false while the viewer flies the camera by hand
};

struct sun_keyframe_deg {
    double time_s = 0.0;
    float elevation_deg = 45.0f;
    float azimuth_deg = 135.0f;
};

struct sun_track {
    std::vector<sun_keyframe_deg> keys;
    float intensity = 3.0f;
};

}  // namespace sylva
