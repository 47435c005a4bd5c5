#pragma once
// Deterministic randomness for the generators: the same seed gives the same numbers on every
// platform and standard library. std::*_distribution is deliberately not used because its output
// is implementation-defined (libstdc++ and libc++ differ), which would break seeded content.
#include <concepts>
#include <cstdint>
#include <utility>
#include <vector>

namespace sylva {

// splitmix64 finaliser (Steele, Lea & Flood 2014, "Fast splittable pseudorandom number
// generators", OOPSLA; constants from Vigna's reference splitmix64.c). A bijective 64-bit mix.
constexpr std::uint64_t mix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

// Derives an independent seed from a seed and any number of integer keys (entity, level, index,
// ...). Order matters: hash_combine(s, 1, 2) != hash_combine(s, 2, 1).
template <std::integral... T>
constexpr std::uint64_t hash_combine(std::uint64_t seed, T... keys) {
    std::uint64_t h = mix64(seed);
    ((h = mix64(h ^ mix64(static_cast<std::uint64_t>(keys) + 0x632be59bd9b4e019ULL))), ...);
    return h;
}

// PCG32, XSH-RR output on a 64-bit LCG (O'Neill 2014, "PCG: A Family of Simple Fast
// Space-Efficient Statistically Good Algorithms for Random Number Generation", HMC-CS-2014-0905;
// multiplier and seeding sequence from pcg32_srandom_r in the reference implementation).
class rng {
public:
    explicit constexpr rng(std::uint64_t seed, std::uint64_t stream = 0)
        : m_increment((mix64(stream) << 1u) | 1u) {
        next_u32();
        m_state += mix64(seed);
        next_u32();
    }

    constexpr std::uint32_t next_u32() {
        const std::uint64_t old = m_state;
        m_state = old * 6364136223846793005ULL + m_increment;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    // [0, 1) from the top 24 bits: every result is exactly representable, so no rounding to 1.
    constexpr float uniform() { return static_cast<float>(next_u32() >> 8) * 0x1.0p-24f; }
    constexpr float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    // Symmetric variation as Weber & Penn write it: "value ± variation".
    constexpr float vary(float value, float variation) { return value + variation * uniform(-1.0f, 1.0f); }

    // [0, 1) with 53 random bits, for world-space positions in metres.
    constexpr double uniform_double() {
        const std::uint64_t hi = next_u32() >> 5;  // 27 bits
        const std::uint64_t lo = next_u32() >> 6;  // 26 bits
        return static_cast<double>((hi << 26) | lo) * 0x1.0p-53;
    }
    constexpr double uniform_double(double lo, double hi) { return lo + (hi - lo) * uniform_double(); }

    // [0, n) without modulo bias (Lemire 2019, "Fast Random Integer Generation in an Interval").
    constexpr std::uint32_t below(std::uint32_t n) {
        std::uint64_t m = std::uint64_t(next_u32()) * n;
        auto low = static_cast<std::uint32_t>(m);
        if (low < n) {
            const std::uint32_t threshold = (0u - n) % n;
            while (low < threshold) {
                m = std::uint64_t(next_u32()) * n;
                low = static_cast<std::uint32_t>(m);
            }
        }
        return static_cast<std::uint32_t>(m >> 32);
    }

private:
    std::uint64_t m_state = 0;
    std::uint64_t m_increment;
};

// Fisher–Yates shuffle of `values` in groups of `stride` consecutive elements (a line's two
// vertices stay together), from the back, with rng::below: the same order on every platform.
template <class T>
void shuffle_groups(std::vector<T>& values, std::size_t stride, rng& random) {
    const std::size_t groups = stride ? values.size() / stride : 0;
    for (std::size_t i = groups; i > 1; --i) {
        const std::size_t j = random.below(std::uint32_t(i));
        for (std::size_t k = 0; k < stride; ++k) std::swap(values[(i - 1) * stride + k], values[j * stride + k]);
    }
}

}  // namespace sylva
