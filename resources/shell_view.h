#pragma once
// Behrendt 2005 §3: what the shells need besides their tiles (components/shell_tile.h). Set at
// spawn from the shell textures and the ladders (setup/spawn_scenario.cpp); the fade distances
// are rewritten every frame by update_shells from the camera. No shells: `active` is false.
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace sylva {

// Slices closer on screen than this are merged (lod/shell_levels.h p_min), and the share of a
// level's range over which its pairs move together.
inline constexpr float k_shell_min_spacing_px = 2.0f;
inline constexpr float k_shell_merge_band = 0.5f;

struct shell_view {
    bool active = false;
    glm::dvec3 terrain_origin{0.0};  // world position of the terrain's local origin
    float slice_height_m = 0.0f;  // the bake's slab thickness
    std::uint32_t max_level = 0;  // the pyramid's top level (one slice)
    float slant = 1.0f;           // f of Eq. 2 (the paper's 1)
    // By species, the mean scale of its plants' populations (the plant size the fade assumes).
    std::vector<float> mean_scale;
    // The handover from the plants' ladder (§3.3 end), this frame: the shell rung's switch size S
    // and band h of the first species whose ladder reaches it, and that species' plant diameter
    // at its mean scale. A plant of that size hands over to the shell between sizes S(1 + h) and
    // S; the shell fades in over the same distances.
    float below_px = 0.0f;
    float band = 0.0f;
    float plant_diameter_m = 0.0f;
    // This frame's fade: the shell is transparent nearer than start, whole beyond end.
    float fade_start_m = 0.0f;
    float fade_end_m = 0.0f;
};

}  // namespace sylva
