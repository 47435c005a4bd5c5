#pragma once
// The sky around the scene and its spherical-harmonics projection (3 bands, 9 coefficients per
// channel): the analytic Preetham sky, or an HDR environment map when the scenario names one.
// `sky_revision` changes whenever the sky or sun changes; project_environment re-projects only
// then. Writer: spawn_scenario (settings, map_radiance_sh), update_sun (revision),
// project_environment (everything below "written by project_environment").
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

namespace sylva {

// The inputs of the last full integration of the analytic sky, which was made with the sun at
// the environment's reference azimuth. While they stay equal, a sun that only moves in azimuth
// is an exact rotation about y of this projection (Preetham's sky depends on the sun only
// through angles to it), so project_environment rotates instead of integrating again.
struct sky_projection_cache {
    bool valid = false;
    float sun_elevation_deg = 0.0f;
    float turbidity = 0.0f;
    float sky_intensity = 0.0f;
    glm::vec3 ground_albedo{0.0f};
    std::array<glm::vec3, 9> radiance_sh{};  // sun at reference_azimuth_deg
};

struct environment {
    float turbidity = 3.0f;
    float sky_intensity = 1.0f;  // scales the analytic sky, or the environment map
    glm::vec3 ground_albedo{0.25f, 0.22f, 0.16f};
    std::uint64_t sky_revision = 1;
    std::uint64_t projected_revision = 0;
    // Degrees clockwise from north (sky_model.h). The analytic sky is integrated with the sun at
    // this azimuth and rotated to the sun's, and the map turns with the sun's azimuth from it;
    // spawn_scenario sets the first sun keyframe's. Every projection is then a pure function of
    // the current sun and settings, whatever path the sun took (deterministic under seeking).
    float reference_azimuth_deg = 140.0f;
    // The environment map (lighting/environment_map.h), when the scenario names one:
    // its radiance projection as the file lies (no rotation, intensity 1) and the scenario's
    // extra turn about y. It then replaces the analytic sky in radiance_sh and irradiance_sh.
    bool has_map = false;
    float map_rotation_deg = 0.0f;
    std::array<glm::vec3, 9> map_radiance_sh{};

    // Written by project_environment.
    sky_projection_cache sky_cache;
    // Radiance SH coefficients of the sky and ground without the sun (the sun is a directional
    // light): what per-vertex transfer vectors are dotted with (Behrendt 2005 §4).
    std::array<glm::vec3, 9> radiance_sh{};
    // Irradiance SH coefficients (radiance_sh convolved with the clamped cosine), per channel.
    std::array<glm::vec3, 9> irradiance_sh{};
};

}  // namespace sylva
