#include "models/terrain.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>

#include "models/noise.h"

namespace sylva {
namespace {

constexpr double k_rad_to_deg = 57.295779513082320876;

// Continuous grid coordinate (0 .. resolution-1) of a world coordinate, clamped to the field.
double grid_coordinate(const heightfield& f, double world) {
    const double g = (world + 0.5 * f.size_m) / f.spacing();
    return std::clamp(g, 0.0, double(f.resolution - 1));
}

struct gradient {
    double dx;  // dh/dx
    double dz;  // dh/dz
};

// Central differences over one grid spacing: the slope a walker feels at the scale the terrain
// is sampled at. The sample points are clamped to the field and the difference divided by their
// actual distance, so at the border it becomes a one-sided difference instead of halving.
gradient gradient_at(const heightfield& f, double x, double z) {
    const double half = 0.5 * f.size_m;
    const double h = 0.5 * f.spacing();
    const double x0 = std::max(x - h, -half);
    const double x1 = std::min(x + h, half);
    const double z0 = std::max(z - h, -half);
    const double z1 = std::min(z + h, half);
    const double cx = std::clamp(x, -half, half);
    const double cz = std::clamp(z, -half, half);
    return {(double(f.height_at(x1, cz)) - double(f.height_at(x0, cz))) / std::max(x1 - x0, 1e-12),
            (double(f.height_at(cx, z1)) - double(f.height_at(cx, z0))) / std::max(z1 - z0, 1e-12)};
}

void validate(double size_m, std::uint32_t resolution) {
    if (resolution < 2) throw std::invalid_argument("generate_terrain: resolution must be >= 2");
    if (!(size_m > 0.0)) throw std::invalid_argument("generate_terrain: size_m must be > 0");
}

}  // namespace

float heightfield::height_at(double x, double z) const {
    const double gx = grid_coordinate(*this, x);
    const double gz = grid_coordinate(*this, z);
    const auto c0 = std::min(static_cast<std::uint32_t>(gx), resolution - 2);
    const auto r0 = std::min(static_cast<std::uint32_t>(gz), resolution - 2);
    const double fx = gx - c0;
    const double fz = gz - r0;
    const double top = at(c0, r0) + (double(at(c0 + 1, r0)) - at(c0, r0)) * fx;
    const double bottom = at(c0, r0 + 1) + (double(at(c0 + 1, r0 + 1)) - at(c0, r0 + 1)) * fx;
    return static_cast<float>(top + (bottom - top) * fz);
}

glm::vec3 heightfield::normal_at(double x, double z) const {
    const gradient g = gradient_at(*this, x, z);
    // Normal of the surface y = h(x, z) is (-dh/dx, 1, -dh/dz), normalised.
    return glm::normalize(glm::vec3(float(-g.dx), 1.0f, float(-g.dz)));
}

float heightfield::slope_deg_at(double x, double z) const {
    const gradient g = gradient_at(*this, x, z);
    return static_cast<float>(std::atan(std::hypot(g.dx, g.dz)) * k_rad_to_deg);
}

heightfield generate_terrain(double size_m, std::uint32_t resolution, float height_m,
                             std::uint32_t octaves, float frequency, std::uint64_t seed) {
    validate(size_m, resolution);
    heightfield f;
    f.resolution = resolution;
    f.size_m = size_m;
    f.heights.resize(std::size_t(resolution) * resolution);
    const fbm_settings settings{std::max(octaves, 1u), 2.0, 0.5f, 0};
    const double spacing = f.spacing();
    const double half = 0.5 * size_m;
    for (std::uint32_t row = 0; row < resolution; ++row) {
        for (std::uint32_t column = 0; column < resolution; ++column) {
            // World-space coordinates, so a terrain of another resolution is the same landscape.
            const double x = (column * spacing - half) * frequency;
            const double z = (row * spacing - half) * frequency;
            f.heights[std::size_t(row) * resolution + column] = 0.5f * height_m * fbm(x, z, seed, settings);
        }
    }
    const auto [lo, hi] = std::minmax_element(f.heights.begin(), f.heights.end());
    f.min_height = *lo;
    f.max_height = *hi;
    return f;
}

mesh_data terrain_mesh(const heightfield& field, float uv_scale_m) {
    if (field.resolution < 2) throw std::invalid_argument("terrain_mesh: empty heightfield");
    const std::uint32_t n = field.resolution;
    const double spacing = field.spacing();
    const double half = 0.5 * field.size_m;
    const float uv_per_m = uv_scale_m > 0.0f ? 1.0f / uv_scale_m : 1.0f;
    mesh_data mesh;
    mesh.vertices.reserve(std::size_t(n) * n);
    for (std::uint32_t row = 0; row < n; ++row) {
        for (std::uint32_t column = 0; column < n; ++column) {
            const double x = column * spacing - half;
            const double z = row * spacing - half;
            vertex v;
            v.position = glm::vec3(float(x), field.at(column, row), float(z));
            v.normal = field.normal_at(x, z);
            v.uv = glm::vec2(float(x) * uv_per_m, float(z) * uv_per_m);
            mesh.vertices.push_back(v);
        }
    }
    mesh.indices.reserve(std::size_t(n - 1) * (n - 1) * 6);
    for (std::uint32_t row = 0; row + 1 < n; ++row) {
        for (std::uint32_t column = 0; column + 1 < n; ++column) {
            const std::uint32_t i = row * n + column;
            // Counter-clockwise seen from +y (x right, z towards the viewer).
            mesh.indices.insert(mesh.indices.end(), {i, i + n, i + 1, i + 1, i + n, i + n + 1});
        }
    }
    mesh.submeshes.push_back({0, std::uint32_t(mesh.indices.size()), material_kind::ground});
    mesh.bounds_min = glm::vec3(float(-half), field.min_height, float(-half));
    mesh.bounds_max = glm::vec3(float(half), field.max_height, float(half));
    return mesh;
}

}  // namespace sylva
