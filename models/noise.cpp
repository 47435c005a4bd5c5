#include "models/noise.h"

#include <array>
#include <cmath>

#include "models/random.h"

namespace sylva {
namespace {

// Perlin 2002, "Improving Noise": 6t^5 - 15t^4 + 10t^3, C2-continuous so the second derivative
// (visible as creases in lighting of a heightfield) has no jumps at cell borders.
double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

double lerp(double a, double b, double t) { return a + (b - a) * t; }

std::int64_t wrap(std::int64_t i, std::uint32_t period) {
    if (period == 0) return i;
    const auto p = static_cast<std::int64_t>(period);
    return ((i % p) + p) % p;
}

std::uint64_t lattice_hash(std::int64_t ix, std::int64_t iy, std::uint64_t seed) {
    return hash_combine(seed, ix, iy);
}

// Eight unit gradients spaced 45 degrees apart: enough isotropy for terrain and textures, and a
// table lookup instead of a cos/sin per corner.
constexpr double k_diagonal = 0.70710678118654752;
constexpr std::array<std::array<double, 2>, 8> k_gradients{{
    {1.0, 0.0}, {k_diagonal, k_diagonal}, {0.0, 1.0}, {-k_diagonal, k_diagonal},
    {-1.0, 0.0}, {-k_diagonal, -k_diagonal}, {0.0, -1.0}, {k_diagonal, -k_diagonal},
}};

double corner(std::int64_t ix, std::int64_t iy, double dx, double dy, std::uint64_t seed) {
    const auto& g = k_gradients[lattice_hash(ix, iy, seed) >> 61];
    return g[0] * dx + g[1] * dy;
}

double corner_value(std::int64_t ix, std::int64_t iy, std::uint64_t seed) {
    return static_cast<double>(lattice_hash(ix, iy, seed) >> 11) * 0x1.0p-53;
}

struct cell {
    std::int64_t x0, y0, x1, y1;
    double fx, fy;
};

cell locate(double x, double y, std::uint32_t period) {
    const double floor_x = std::floor(x);
    const double floor_y = std::floor(y);
    const auto ix = static_cast<std::int64_t>(floor_x);
    const auto iy = static_cast<std::int64_t>(floor_y);
    return {wrap(ix, period), wrap(iy, period), wrap(ix + 1, period), wrap(iy + 1, period),
            x - floor_x, y - floor_y};
}

template <class Octave>
float sum_octaves(double x, double y, std::uint64_t seed, const fbm_settings& s, Octave octave) {
    double sum = 0.0;
    double amplitude = 1.0;
    double total = 0.0;
    double frequency = 1.0;
    double period = s.period;
    for (std::uint32_t i = 0; i < s.octaves; ++i) {
        // A different seed per octave stops the lattice points of all octaves lining up at 0.
        sum += amplitude * octave(x * frequency, y * frequency, hash_combine(seed, i),
                                  static_cast<std::uint32_t>(period));
        total += amplitude;
        amplitude *= s.gain;
        frequency *= s.lacunarity;
        period *= s.lacunarity;
    }
    return total > 0.0 ? static_cast<float>(sum / total) : 0.0f;
}

}  // namespace

float gradient_noise(double x, double y, std::uint64_t seed, std::uint32_t period) {
    const cell c = locate(x, y, period);
    const double n00 = corner(c.x0, c.y0, c.fx, c.fy, seed);
    const double n10 = corner(c.x1, c.y0, c.fx - 1.0, c.fy, seed);
    const double n01 = corner(c.x0, c.y1, c.fx, c.fy - 1.0, seed);
    const double n11 = corner(c.x1, c.y1, c.fx - 1.0, c.fy - 1.0, seed);
    const double u = fade(c.fx);
    const double v = fade(c.fy);
    // 2D gradient noise with unit gradients peaks at sqrt(1/2); scale it to about [-1, 1].
    return static_cast<float>(lerp(lerp(n00, n10, u), lerp(n01, n11, u), v) / k_diagonal);
}

float value_noise(double x, double y, std::uint64_t seed, std::uint32_t period) {
    const cell c = locate(x, y, period);
    const double u = fade(c.fx);
    const double v = fade(c.fy);
    const double a = lerp(corner_value(c.x0, c.y0, seed), corner_value(c.x1, c.y0, seed), u);
    const double b = lerp(corner_value(c.x0, c.y1, seed), corner_value(c.x1, c.y1, seed), u);
    return static_cast<float>(lerp(a, b, v));
}

float fbm(double x, double y, std::uint64_t seed, const fbm_settings& settings) {
    return sum_octaves(x, y, seed, settings, gradient_noise);
}

float fbm_value(double x, double y, std::uint64_t seed, const fbm_settings& settings) {
    return sum_octaves(x, y, seed, settings, value_noise);
}

}  // namespace sylva
