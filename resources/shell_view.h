#pragma once
// Behrendt 2005 §3: what the shells need besides their tiles (components/shell_tile.h). Set at
// spawn from the shell textures and the ladders (setup/spawn_scenario.cpp); the fade distances
// are rewritten every frame by update_shells from the camera. No shells: `active` is false.
#include <algorithm>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace sylva {

// Slices closer on screen than this are merged (lod/shell_levels.h p_min), and the share of a
// level's range over which its pairs move together. One pixel: at a grazing view the slices'
// spacing is also how often a ray through the canopy meets a sample, and merged at 2 px apart
// the far field lost crowns between the samples. On docs/measure_shells.py's far fields (3
// frames, one bench per value) 2 -> 1 px took flat slices at 5° from SSIM 0.9664 to 0.9686
// (coverage IoU 0.936 -> 0.948) and f 0.25 on landscape's own view from 0.9830 to 0.9847, for
// about a third more shell time there (f 0.25 74 -> 87 ms); 0.5 px measured the same as 1.
inline constexpr float k_shell_min_spacing_px = 1.0f;
inline constexpr float k_shell_merge_band = 0.5f;
// A tile's slices follow the coarsest grid of the ground whose vertical error is at most this
// many pixels on screen (components/shell_tile.h).
inline constexpr float k_shell_ground_error_px = 1.0f;

struct shell_view {
    bool active = false;
    glm::dvec3 terrain_origin{0.0};  // world position of the terrain's local origin
    float slice_height_m = 0.0f;  // the bake's slab thickness
    std::uint32_t max_level = 0;  // the pyramid's top level (one slice)
    float slant = 1.0f;           // f of Eq. 2 (the paper's 1; scenario shells.slant)
    float slant_reach_m = 0.0f;   // the ground's own triangles' reach: every grid's shift within f times it
    bool half_resolution = true;  // blended in the half-size shell layer (passes/shell_pass.h)
    // By species, the mean scale of its plants' populations (the plant size the fade assumes).
    std::vector<float> mean_scale;
    // The handover from the plants' ladder (§3.3 end), this frame: the plant diameter (at its
    // mean scale) of the species whose ladder hands over farthest. A plant of that size crosses
    // its shell rung's band (sizes S(1 + h) to S) between fade_start_m and fade_end_m; the shell
    // fades in over those distances, and every plant on a ladder ending in the shell hands over
    // there (lod/ladder.h choose_rung_with_shell).
    float plant_diameter_m = 0.0f;
    float pixels_per_radian = 0.0f;  // this frame's viewport height over the field of view
    // This frame's fade: the shell is transparent nearer than start, whole beyond end.
    float fade_start_m = 0.0f;
    float fade_end_m = 0.0f;
};

// The shell's opacity at `distance_m` from the camera (0 .. 1), linear across the fade band as
// the shell's fragment shader computes it (shaders/shell.frag); 0 when the shells draw nothing.
inline float shell_fade_at(const shell_view& v, float distance_m) {
    if (!v.active || !(v.fade_end_m > 0.0f)) return 0.0f;
    if (!(v.fade_end_m > v.fade_start_m)) return distance_m >= v.fade_end_m ? 1.0f : 0.0f;
    return std::clamp((distance_m - v.fade_start_m) / (v.fade_end_m - v.fade_start_m), 0.0f, 1.0f);
}

}  // namespace sylva
