#pragma once
// Lattice noise shared by the terrain and the texture generators. Written here rather than taken
// from a library because the results must be bit-identical for a seed on every platform and the
// textures need noise that wraps with a chosen period (to tile seamlessly).
#include <cstdint>

namespace sylva {

// Gradient noise (Perlin 2002, "Improving Noise", SIGGRAPH): quintic fade, gradients picked by a
// hash of the lattice point. Roughly in [-1, 1], 0 at every lattice point. With period > 0 the
// lattice wraps every `period` cells in x and y, so the noise tiles over [0, period)^2.
float gradient_noise(double x, double y, std::uint64_t seed, std::uint32_t period = 0);

// Value noise: smoothly interpolated random values in [0, 1] at lattice points; cheaper and
// blobbier than gradient noise. Same period convention.
float value_noise(double x, double y, std::uint64_t seed, std::uint32_t period = 0);

struct fbm_settings {
    std::uint32_t octaves = 5;
    double lacunarity = 2.0;  // frequency multiplier per octave
    float gain = 0.5f;        // amplitude multiplier per octave
    std::uint32_t period = 0; // of the first octave; later octaves wrap at period * lacunarity^i
};

// Fractional Brownian motion: sum of octaves of gradient noise (Musgrave, in Ebert et al. 2003,
// "Texturing & Modeling", ch. 16 fBm). Normalised by the sum of amplitudes, so about [-1, 1].
// Tiling needs an integer lacunarity.
float fbm(double x, double y, std::uint64_t seed, const fbm_settings& settings);

// The same sum over value noise, in [0, 1].
float fbm_value(double x, double y, std::uint64_t seed, const fbm_settings& settings);

}  // namespace sylva
