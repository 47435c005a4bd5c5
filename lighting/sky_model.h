#pragma once
// An analytic clear sky used as the scene's environment: Preetham, Shirley and Smits 1999,
// "A Practical Analytic Model for Daylight" (Perez sky distribution, zenith luminance and
// chromaticity from turbidity and sun angle), converted xyY -> linear sRGB (Rec. 709, D65).
// The lower hemisphere is the ground, a Lambertian plane lit by the sky.
//
// Directions: world space, y up, x east, -z north; unit vectors.
// Units: the model's luminance (kcd/m^2) is scaled so that sky_intensity = 1 gives radiance
// of roughly 0.5-1.5 at mid sun elevations, matching the renderer's sun intensity of a few units.
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "lighting/spherical_harmonics.h"

namespace sylva {

struct sky_model {
    glm::vec3 sun_direction{0.0f, 1.0f, 0.0f};  // unit, towards the sun
    float turbidity = 3.0f;                     // Preetham's T, clamped to [2, 10]; NaN -> 3
    float sky_intensity = 1.0f;                 // multiplies the whole sky (and the ground)
    glm::vec3 ground_albedo{0.25f, 0.22f, 0.16f};
    // Optional direct-sun irradiance on a plane facing the sun. It is not part of the sky's
    // radiance (the renderer draws the sun as a directional light), but when set it also lights
    // the ground, whose bounce then includes sunlight: E_ground += sun_irradiance * max(0, sun.y).
    glm::vec3 sun_irradiance{0.0f};

    // Radiance arriving from `unit_dir` (looking along it). No sun disk; the Perez circumsolar
    // term brightens the sky around the sun. Finite and > 0 for every direction and sun angle.
    glm::vec3 radiance(glm::vec3 unit_dir) const;
};

// Radiance of the ground: albedo * E / pi, where E is the irradiance on a horizontal plane from
// the sky's upper hemisphere (plus sun_irradiance * max(0, sun.y)). E is integrated
// numerically once per (sun elevation, turbidity) and memoised per thread.
glm::vec3 ground_radiance(const sky_model& sky);

// 9-term SH projection of the sky radiance (upper hemisphere sky, lower hemisphere ground).
sh9_rgb project_sky(const sky_model& sky, int samples_theta = 64, int samples_phi = 128);

// Unit vector towards the sun. Elevation in degrees above the horizon; azimuth in degrees
// clockwise from north seen from above: 0 = north = -z, 90 = east = +x, 180 = south = +z.
glm::vec3 sun_direction_from_angles(float elevation_deg, float azimuth_deg);

// The rotation about world y (up) that adds `delta_azimuth_deg` to every direction's azimuth in
// the convention above: sun_direction_from_angles(e, a) goes to sun_direction_from_angles(e,
// a + delta). Clockwise seen from above, so it is a right-handed rotation by -delta about +y.
glm::mat3 azimuth_rotation(float delta_azimuth_deg);

// The sun's colour after atmospheric extinction along its slant path (reddish near the horizon),
// per linear RGB channel, normalised so that the overhead sun through a clear (T = 2) atmosphere
// is about 1 in luminance; multiply by the sun's intensity. Zero once the disk has set.
glm::vec3 sun_radiance_color(float elevation_rad, float turbidity);

}  // namespace sylva
