#include "lod/ground_grid.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sylva {

std::uint8_t coarsest_ground_grid(std::span<const float> grid_error_m, float nearest_m,
                                  float pixels_per_radian, float tolerance_px) {
    std::uint8_t grid = 0;
    while (grid + 1u < grid_error_m.size() &&
           grid_error_m[grid + 1u] * pixels_per_radian <= tolerance_px * nearest_m)
        ++grid;
    return grid;
}

std::vector<float> ground_skirt_depths(std::span<const float> errors,
                                       std::span<const float> coarsest,
                                       std::uint32_t tiles_per_side) {
    const std::size_t n = std::size_t(tiles_per_side) * tiles_per_side;
    if (errors.size() != n || coarsest.size() != n)
        throw std::invalid_argument("ground_skirt_depths: " + std::to_string(tiles_per_side) +
                                    "^2 tiles need as many errors (" +
                                    std::to_string(errors.size()) + " and " +
                                    std::to_string(coarsest.size()) + " given)");
    std::vector<float> depths(n);
    for (std::uint32_t z = 0; z < tiles_per_side; ++z)
        for (std::uint32_t x = 0; x < tiles_per_side; ++x) {
            const std::size_t t = std::size_t(z) * tiles_per_side + x;
            float neighbours = 0.0f;
            if (x > 0) neighbours = std::max(neighbours, coarsest[t - 1]);
            if (x + 1 < tiles_per_side) neighbours = std::max(neighbours, coarsest[t + 1]);
            if (z > 0) neighbours = std::max(neighbours, coarsest[t - tiles_per_side]);
            if (z + 1 < tiles_per_side)
                neighbours = std::max(neighbours, coarsest[t + tiles_per_side]);
            depths[t] = errors[t] + neighbours;
        }
    return depths;
}

}  // namespace sylva
