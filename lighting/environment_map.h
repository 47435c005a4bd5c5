#pragma once
// HDR environment maps: an equirectangular (latitude-longitude) .hdr or .exr image read to
// linear RGB with OpenImageIO and projected to 3-band SH, replacing the analytic sky when a
// scenario names one (scenarios/scenario.h, environment.map). Nothing is cached on disk:
// reading and projecting a 2k map takes well under a second.
//
// Orientation (world: y up, x east, -z north; the renderer's sky texture uses the same):
//
//   column u = (i + 0.5) / width     azimuth phi = (u - 0.5) * 360 deg, clockwise from north
//                                     seen from above (as sun azimuth, sky_model.h):
//       u = 0      0.25     0.5      0.75     1
//           south  west     north    east     south
//           (+z)   (-x)     (-z)     (+x)     (+z)
//   row v = (j + 0.5) / height       polar angle theta = v * 180 deg from up: row 0 is the
//                                     zenith (+y), the middle row the horizon, the last the
//                                     nadir (the ground under the scene).
//
//   direction = (sin theta sin phi, cos theta, -sin theta cos phi)
#include <cstddef>
#include <filesystem>
#include <vector>

#include "lighting/spherical_harmonics.h"

namespace sylva {

struct environment_map {
    int width = 0;  // = 2 * height
    int height = 0;
    std::vector<float> rgb;  // linear radiance, 3 floats per texel, rows top (zenith) down
    // Texels that were NaN, infinite or negative in the file and were set to 0 (radiance is
    // finite and non-negative; one bad texel must not poison every coefficient).
    std::size_t sanitised_texels = 0;
};

// Reads the file's first three channels as linear RGB float. Throws std::runtime_error naming
// the file and the problem: missing, unreadable, not float data (8-bit images are display
// encoded, not radiance), fewer than 3 channels, or not 2:1.
environment_map load_environment_map(const std::filesystem::path& path);

// Radiance SH of the map. The map is constant over each texel, so every texel contributes its
// radiance times the exact integral of each basis function over the texel's (theta, phi) cell;
// for band 0 that is the texel's solid angle (cos theta0 - cos theta1) dphi, i.e.
// cos(latitude) dtheta dphi to second order. A constant or hemispherical map thus projects
// exactly, with no quadrature error. Sums in double in a fixed order: deterministic.
sh9_rgb project_environment_map(const environment_map& map);

// The map reduced to width x height for the renderer's sky texture: each output texel is the
// solid-angle-weighted mean of the source texels whose centres fall in it (the nearest source
// texel when none does, i.e. when the map is smaller than the output).
environment_map downsample_environment_map(const environment_map& map, int width, int height);

// The world direction of texel (column, row) of a width x height map (orientation above).
glm::vec3 environment_map_direction(int column, int row, int width, int height);

}  // namespace sylva
