#pragma once
// Which of the view's shadow cascades can hold a receiver. A cascade's slice of the view
// frustum (between two split distances) that lies wholly above the ground and every plant over
// it shades nothing, and nothing needs drawing into its map: on landscape the camera flies
// 100-120 m up and the two near slices are air. The ground's and the plants' highest points are
// kept on a coarse grid of the world's x and z (built once at spawn), and a slice is tested by
// its lowest corner against the highest receiver under its footprint.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

#include "components/camera.h"
#include "models/terrain/terrain.h"

namespace sylva {

struct receiver_heights {
    glm::dvec2 min_xz{0.0};  // world x, z of the grid's corner
    double cell_m = 1.0;
    std::uint32_t cells = 0;  // per side; 0: nothing known, every slice may hold receivers
    std::vector<float> top;   // cells², rows of z, columns of x: the highest receiver, world y

    // Raises every cell under the square [x − r, x + r] x [z − r, z + r] to at least y.
    void raise(double x, double z, double r, float y);
    // The highest receiver over the box [lo, hi] of world x, z; +inf where it leaves the grid
    // (outside it nothing is known).
    float highest(glm::dvec2 lo, glm::dvec2 hi) const;
};

// The ground's highest points on `cells` x `cells` cells over the heightfield, which lies at
// `offset` (the scenario's world offset). Plants are added with raise().
receiver_heights make_receiver_heights(const heightfield& field, glm::dvec3 offset,
                                       std::uint32_t cells);

// True unless the slice of `cam`'s view frustum between view depths `near` and `far` lies wholly
// above every receiver under it (its lowest corner higher than the highest of them).
bool slice_may_hold_receivers(const receiver_heights& receivers, const camera& cam, float near,
                              float far);

}  // namespace sylva
