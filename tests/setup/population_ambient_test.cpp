// Luft 2007 §5 kept instanced (setup/population_ambient.h, components/population_ambient.h): the
// packing round-trips, the shader's trilinear blend is reproduced, and the factor at a corner is
// Eq. 4 of the population's field over Eq. 4 of the plant's own, checked by hand.
#include "setup/population_ambient.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

namespace sylva {
namespace {

TEST(population_ambient, the_default_darkens_nothing_and_packing_round_trips) {
    const population_ambient none;
    for (int c = 0; c < k_population_corners; ++c) EXPECT_EQ(population_factor(none, c), 1.0f);
    EXPECT_EQ(population_half_size(none), 1.0f);
    // All ones at h = 1 pack to exactly the default, so a lone plant's instance is unchanged.
    std::array<float, 8> ones;
    ones.fill(1.0f);
    EXPECT_EQ(pack_population_ambient(ones, 1.0f).packed, none.packed);

    const std::array<float, 8> f{0.0f, 1.0f / 63.0f, 0.5f, 0.25f, 1.0f, 0.75f, 0.4f, 0.9f};
    const population_ambient p = pack_population_ambient(f, 6.5f);
    EXPECT_EQ(population_half_size(p), 6.5f);  // exact in half precision
    for (int c = 0; c < k_population_corners; ++c)
        EXPECT_NEAR(population_factor(p, c), f[std::size_t(c)], 0.5f / 63.0f + 1e-6f) << "corner " << c;
    // Corner 5 straddles the two words: 0.75 -> 47 = 0b101111, bits 30..35.
    EXPECT_EQ(population_factor(p, 5), 47.0f / 63.0f);
}

TEST(population_ambient, the_blend_is_trilinear_over_the_box) {
    std::array<float, 8> f{};
    for (int c = 0; c < 8; ++c) f[std::size_t(c)] = float(c) / 7.0f;
    const population_ambient p = pack_population_ambient(f, 2.0f);
    // The box is [-2, 2] x [0, 4] x [-2, 2]: its corners give the corners' values...
    EXPECT_NEAR(population_factor_at(p, -2.0f, 0.0f, -2.0f), population_factor(p, 0), 1e-6f);
    EXPECT_NEAR(population_factor_at(p, 2.0f, 4.0f, 2.0f), population_factor(p, 7), 1e-6f);
    EXPECT_NEAR(population_factor_at(p, 2.0f, 0.0f, -2.0f), population_factor(p, 1), 1e-6f);
    // ... its centre their mean, and points outside clamp to the box.
    float mean = 0.0f;
    for (int c = 0; c < 8; ++c) mean += population_factor(p, c) / 8.0f;
    EXPECT_NEAR(population_factor_at(p, 0.0f, 2.0f, 0.0f), mean, 1e-6f);
    EXPECT_NEAR(population_factor_at(p, 9.0f, -3.0f, -9.0f), population_factor(p, 1), 1e-6f);
}

TEST(population_ambient, to_model_undoes_the_instance_pose) {
    // Yaw π/2 (c = 0, s = 1) turns model +x to world −z (shaders/instance.glsl), then scale 2.
    const world_transform t{{10.0, 1.0, 0.0}, glm::half_pi<float>(), 2.0f};
    const glm::vec3 m = to_model(t, {10.0, 1.0, -2.0});
    EXPECT_NEAR(m.x, 1.0f, 1e-6f);
    EXPECT_NEAR(m.y, 0.0f, 1e-6f);
    EXPECT_NEAR(m.z, 0.0f, 1e-6f);
}

// A plant with one generator at its origin (ρ = 1, τ = 0.25) and k_a,min 0.2, d_min 1, n 1, its
// box half size 1: corner 0 is (−1, 0, −1), √2 from its own generator, so its own F = −τ and
// k_a = 1 there. A neighbour whose one generator sits exactly on that corner adds D = 1:
// F = −0.25 + 1 = 0.75, k_a = 0.2 + 0.8 (1 − 0.75) = 0.4, so the factor is 0.4. Corner 1 is 2 m from
// the neighbour's generator: untouched.
TEST(population_ambient, a_neighbours_density_lowers_ka_by_eq4_of_the_summed_field) {
    const implicit_field one({{0.0f, 0.0f, 0.0f}}, 1.0f, 0.25f);
    implicit_settings s;
    s.ka_min = 0.2f;
    s.d_min = 1.0f;
    s.exponent = 1.0f;
    const placed_field self{&one, {{0.0, 0.0, 0.0}, 0.0f, 1.0f}};
    const std::array<float, 8> alone = population_factors(self, s, 1.0f, {});
    for (float f : alone) EXPECT_EQ(f, 1.0f);

    const std::array<placed_field, 1> neighbour{placed_field{&one, {{-1.0, 0.0, -1.0}, 0.0f, 1.0f}}};
    const std::array<float, 8> together = population_factors(self, s, 1.0f, neighbour);
    EXPECT_NEAR(together[0], 0.4f, 1e-6f);
    EXPECT_EQ(together[1], 1.0f);

    // The same neighbour turned and scaled: its generator at model (0.5, 0, 0), yaw π/2, scale 2
    // lands at world (−1, 0, −1) with ρ 2 in the world; D there is still 1.
    const implicit_field offset({{0.5f, 0.0f, 0.0f}}, 1.0f, 0.25f);
    const std::array<placed_field, 1> turned{placed_field{&offset, {{-1.0, 0.0, 0.0}, glm::half_pi<float>(), 2.0f}}};
    EXPECT_NEAR(population_factors(self, s, 1.0f, turned)[0], 0.4f, 1e-5f);

    // Inside its own core (own F ≥ d_min) k_a is k_a,min alone and together: factor 1.
    const implicit_field dense(std::vector<glm::vec3>(4, glm::vec3(-1.0f, 0.0f, -1.0f)), 1.0f, 0.25f);
    const placed_field core{&dense, {{0.0, 0.0, 0.0}, 0.0f, 1.0f}};
    EXPECT_EQ(population_factors(core, s, 1.0f, neighbour)[0], 1.0f);
}

}  // namespace
}  // namespace sylva
