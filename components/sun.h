#pragma once
// The sun: direction towards the sun and its radiance. One entity carries it. Writer:
// update_sun (scenario sun path); read by project_environment and submission (shadows).
#include <glm/vec3.hpp>

namespace sylva {

struct sun {
    glm::vec3 direction{0.3f, 0.8f, 0.4f};  // unit, from the ground towards the sun
    glm::vec3 color{1.0f, 0.95f, 0.85f};
    float intensity = 3.0f;  // irradiance scale of the direct light
    float elevation_deg = 50.0f;
    float azimuth_deg = 140.0f;
};

}  // namespace sylva
