#pragma once
// The terrain: a square heightfield centred on the origin, generated from fBm gradient noise,
// and the grid mesh the renderer draws for it.
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "models/mesh.h"

namespace sylva {

struct heightfield {
    std::uint32_t resolution = 0;  // vertices per side (>= 2)
    double size_m = 0.0;           // side length; spans [-size/2, size/2] in x and z
    std::vector<float> heights;    // row-major: z rows, x columns, resolution^2
    float min_height = 0.0f;
    float max_height = 0.0f;

    double spacing() const { return size_m / double(resolution - 1); }
    float at(std::uint32_t column, std::uint32_t row) const {
        return heights[std::size_t(row) * resolution + column];
    }
    // Bilinear height at world x, z (metres from the centre); clamped to the edge outside.
    float height_at(double x, double z) const;
    // Unit surface normal of the bilinear surface (central differences of height_at).
    glm::vec3 normal_at(double x, double z) const;
    // Angle between the surface and the horizontal plane, degrees.
    float slope_deg_at(double x, double z) const;
};

// fBm of gradient noise (Perlin 2002; Musgrave's fBm), `frequency` in cycles per metre for the
// first octave, heights within about ±height_m/2 (height_m is the peak-to-valley scale).
heightfield generate_terrain(double size_m, std::uint32_t resolution, float height_m,
                             std::uint32_t octaves, float frequency, std::uint64_t seed);

// One vertex per height sample, smooth normals, one material_kind::ground sub-mesh; positions
// relative to the terrain centre; uv = world xz / uv_scale_m (the texture repeats every
// uv_scale_m metres).
mesh_data terrain_mesh(const heightfield& field, float uv_scale_m);

}  // namespace sylva
