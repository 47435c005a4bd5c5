#pragma once
// The sky around the scene and its spherical-harmonics projection (3 bands, 9 coefficients per
// channel). `sky_revision` changes whenever the sky or sun changes; project_environment
// re-projects only then. Writer: update_sun (revision), project_environment (coefficients).
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

namespace sylva {

struct environment {
    float turbidity = 3.0f;
    float sky_intensity = 1.0f;
    glm::vec3 ground_albedo{0.25f, 0.22f, 0.16f};
    std::uint64_t sky_revision = 1;
    std::uint64_t projected_revision = 0;
    // Irradiance SH coefficients (radiance convolved with the clamped cosine), per channel.
    std::array<glm::vec3, 9> irradiance_sh{};
    // Radiance SH coefficients of the sky and ground (no sun), per channel: what precomputed
    // radiance transfer vectors are dotted with.
    std::array<glm::vec3, 9> radiance_sh{};
};

}  // namespace sylva
