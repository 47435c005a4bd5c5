#pragma once
// Luft 2007 §5 for a population: "it is possible to compute the implicit surface for a plant
// population ... a small tree that is naturally darkened by a nearby large tree", which the paper
// says "cannot be combined with instancing" because the per-vertex k_a then differs per tree.
// Sylva keeps instancing by storing, per instance, what the neighbours change: the factor
// k_a(population) / k_a(own plant) at the 8 corners of a box around the plant (model space), which
// every vertex shader interpolates trilinearly and multiplies into the k_a its model carries
// (shaders/instance.glsl population_ambient). Writer: spawn (setup/population_ambient.h); read by
// build_draw_list into instance_gpu. Present only when a species asks for it (species.implicit
// .population): a scene that does not pays nothing for it.
//
// Packing (8 bytes, instance_gpu::population, read as one little-endian 64-bit word): corner
// c = ix + 2 iy + 4 iz of the box [-h, h] x [0, 2h] x [-h, h] holds round(63 x factor) in bits
// 6c .. 6c + 5 (corner 5 straddles the two 32-bit halves); bits 48..63 hold h, metres in the
// species' model space, as an IEEE half (GLSL unpackHalf2x16).
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/gtc/packing.hpp>

namespace sylva {

inline constexpr int k_population_corners = 8;
inline constexpr float k_population_levels = 63.0f;  // 6 bits a corner

struct population_ambient {
    std::array<std::uint32_t, 2> packed{0xffffffffu, 0x3c00ffffu};  // every factor 1, h = 1
};
static_assert(sizeof(population_ambient) == 8);

// Factors in 0..1 (clamped) at the corners and the box's half size h > 0.
inline population_ambient pack_population_ambient(const std::array<float, k_population_corners>& factor,
                                                  float half_size_m) {
    std::uint64_t word = std::uint64_t(glm::packHalf1x16(half_size_m)) << 48;
    for (int c = 0; c < k_population_corners; ++c) {
        const float f = factor[std::size_t(c)];
        const auto level = std::uint64_t(std::lround((f > 0.0f ? (f < 1.0f ? f : 1.0f) : 0.0f) * k_population_levels));
        word |= level << (6 * c);
    }
    population_ambient out;
    out.packed = {std::uint32_t(word), std::uint32_t(word >> 32)};
    return out;
}

inline float population_factor(const population_ambient& p, int corner) {
    const std::uint64_t word = std::uint64_t(p.packed[0]) | std::uint64_t(p.packed[1]) << 32;
    return float((word >> (6 * corner)) & 63u) / k_population_levels;
}

inline float population_half_size(const population_ambient& p) {
    return glm::unpackHalf1x16(std::uint16_t(p.packed[1] >> 16));
}

// What the shader computes at model-space position q: the corners' factors blended trilinearly
// over the box (q clamped into it).
inline float population_factor_at(const population_ambient& p, float qx, float qy, float qz) {
    const float h = population_half_size(p);
    auto unit = [](float v) { return v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v); };
    const float u = unit(0.5f * (qx / h + 1.0f)), v = unit(0.5f * qy / h), w = unit(0.5f * (qz / h + 1.0f));
    float sum = 0.0f;
    for (int c = 0; c < k_population_corners; ++c) {
        const float wx = (c & 1) ? u : 1.0f - u, wy = (c & 2) ? v : 1.0f - v, wz = (c & 4) ? w : 1.0f - w;
        sum += wx * wy * wz * population_factor(p, c);
    }
    return sum;
}

}  // namespace sylva
