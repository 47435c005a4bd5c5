#pragma once
// Where a population grows: a density in 0..1 over its placement area, read from a greyscale
// image or made from noise. place_population (models/terrain/placement.h) accepts a candidate with
// probability density(u, v).
#include <cstdint>
#include <filesystem>
#include <vector>

namespace sylva {

struct density_map {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> values;  // 0..1, row-major (height rows of width), covers the area

    // Bilinear between texel centres, clamped at the border. u runs along x (area x0 -> x1,
    // columns), v along z (area z0 -> z1, rows; image row 0 is at z0). An empty map is 1.
    float at(double u, double v) const;
};

// An 8- or 16-bit greyscale PNG (any format OpenImageIO reads; the first channel is used),
// white = 1. Throws std::runtime_error naming the file when it is missing or unreadable.
density_map load_density_map(const std::filesystem::path& path);

// fBm value noise (models/noise.h) thresholded softly: the threshold is the (1 - coverage)
// quantile of the noise, so `coverage` is the fraction of the area at density >= 0.5, and the
// density ramps from 0 to 1 over a band around it (soft patch edges). frequency is in cycles
// across the placement area (lowest octave). coverage 0 gives all zeros, 1 all ones.
// resolution 0 picks one from the frequency (about 64 texels per cycle, 64 .. 1024).
density_map procedural_density(std::uint64_t seed, float frequency, float coverage,
                               std::uint32_t resolution = 0);

}  // namespace sylva
