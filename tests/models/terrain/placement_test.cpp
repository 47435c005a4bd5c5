#include "models/terrain/placement.h"

#include <gtest/gtest.h>

#include <chrono>
#include <glm/geometric.hpp>

namespace sylva {
namespace {

heightfield flat_field(double size) {
    heightfield f;
    f.resolution = 2;
    f.size_m = size;
    f.heights.assign(4, 0.0f);
    return f;
}

TEST(placement, points_inside_area_and_count_honoured_when_there_is_room) {
    const heightfield f = flat_field(200.0);
    const std::array<double, 4> area{-50.0, 10.0, 30.0, 60.0};
    const auto p = place_population(f, area, 500, 1.0f, 0.8f, 1.2f, 90.0f, 1);
    ASSERT_EQ(p.size(), 500u);
    for (const placement& q : p) {
        EXPECT_GE(q.xz.x, area[0]);
        EXPECT_LT(q.xz.x, area[2]);
        EXPECT_GE(q.xz.y, area[1]);
        EXPECT_LT(q.xz.y, area[3]);
        EXPECT_GE(q.scale, 0.8f);
        EXPECT_LE(q.scale, 1.2f);
        EXPECT_GE(q.yaw, 0.0f);
        EXPECT_LT(q.yaw, 6.2832f);
    }
}

TEST(placement, pairwise_spacing_is_respected) {
    const heightfield f = flat_field(100.0);
    const float spacing = 3.0f;
    const auto p = place_population(f, {0.0, 0.0, 40.0, 40.0}, 1000, spacing, 1.0f, 1.0f, 90.0f, 5);
    ASSERT_GT(p.size(), 50u);  // packed: returns fewer than asked, but a fair number
    EXPECT_LT(p.size(), 1000u);
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size(); ++j)
            ASSERT_GE(glm::length(p[i].xz - p[j].xz), double(spacing)) << i << " " << j;
}

TEST(placement, steep_ground_is_rejected) {
    // Left half flat, right half a 45-degree ramp: x in [-10, 0] flat, [0, 10] rising.
    heightfield f;
    f.resolution = 21;
    f.size_m = 20.0;
    for (int row = 0; row < 21; ++row)
        for (int column = 0; column < 21; ++column) f.heights.push_back(column > 10 ? float(column - 10) : 0.0f);
    const auto p = place_population(f, {-10.0, -10.0, 10.0, 10.0}, 400, 0.2f, 1.0f, 1.0f, 30.0f, 2);
    ASSERT_FALSE(p.empty());
    for (const placement& q : p) EXPECT_LE(f.slope_deg_at(q.xz.x, q.xz.y), 30.0f);
    for (const placement& q : p) EXPECT_LT(q.xz.x, 0.6);
}

TEST(placement, same_seed_same_result_and_seeds_differ) {
    const heightfield f = generate_terrain(200.0, 33, 20.0f, 4, 0.01f, 3);
    const std::array<double, 4> area{-100.0, -100.0, 100.0, 100.0};
    const auto a = place_population(f, area, 300, 2.0f, 0.5f, 1.5f, 25.0f, 9);
    const auto b = place_population(f, area, 300, 2.0f, 0.5f, 1.5f, 25.0f, 9);
    const auto c = place_population(f, area, 300, 2.0f, 0.5f, 1.5f, 25.0f, 10);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].xz, b[i].xz);
        EXPECT_EQ(a[i].scale, b[i].scale);
        EXPECT_EQ(a[i].yaw, b[i].yaw);
        EXPECT_EQ(a[i].seed, b[i].seed);
        EXPECT_EQ(a[i].tint, b[i].tint);
    }
    ASSERT_FALSE(c.empty());
    EXPECT_NE(a[0].xz, c[0].xz);
}

TEST(placement, hundred_thousand_plants_are_fast) {
    const heightfield f = generate_terrain(2000.0, 257, 30.0f, 5, 0.004f, 1);
    const auto start = std::chrono::steady_clock::now();
    const auto p = place_population(f, {-1000.0, -1000.0, 1000.0, 1000.0}, 100000, 2.0f, 0.8f, 1.2f, 40.0f, 4);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(p.size(), 100000u);
    EXPECT_LT(seconds, 0.5);
    std::printf("[          ] placed %zu plants in %.1f ms\n", p.size(), seconds * 1e3);
}

TEST(placement, edge_cases) {
    const heightfield f = flat_field(10.0);
    EXPECT_TRUE(place_population(f, {0.0, 0.0, 1.0, 1.0}, 0, 1.0f, 1.0f, 1.0f, 90.0f, 1).empty());
    EXPECT_THROW(place_population(f, {1.0, 0.0, 0.0, 1.0}, 5, 1.0f, 1.0f, 1.0f, 90.0f, 1), std::invalid_argument);
    // Zero spacing: no rejection at all.
    EXPECT_EQ(place_population(f, {0.0, 0.0, 1.0, 1.0}, 50, 0.0f, 1.0f, 1.0f, 90.0f, 1).size(), 50u);
}

// --- placement_rules -------------------------------------------------------------------------

placement_rules rules_for(std::array<double, 4> area, std::uint32_t count, float spacing) {
    placement_rules r;
    r.area = area;
    r.count = count;
    r.min_spacing_m = spacing;
    r.scale_min = 0.8f;
    r.scale_max = 1.2f;
    r.max_slope_deg = 90.0f;
    return r;
}

TEST(placement_rules, old_overload_is_the_rules_overload) {
    const heightfield f = generate_terrain(200.0, 65, 30.0f, 5, 0.01f, 2);
    const auto old =
        place_population(f, {-100.0, -100.0, 100.0, 100.0}, 500, 3.0f, 0.8f, 1.2f, 30.0f, 11);
    placement_rules r = rules_for({-100.0, -100.0, 100.0, 100.0}, 500, 3.0f);
    r.max_slope_deg = 30.0f;
    const auto now = place_population(f, r, 11);
    ASSERT_EQ(old.size(), now.size());
    for (std::size_t i = 0; i < old.size(); ++i) {
        EXPECT_EQ(old[i].xz, now[i].xz);
        EXPECT_EQ(old[i].seed, now[i].seed);
    }
}

TEST(placement_rules, altitude_rule_keeps_plants_within_the_band) {
    const heightfield f = generate_terrain(200.0, 65, 40.0f, 5, 0.01f, 2);
    placement_rules r = rules_for({-100.0, -100.0, 100.0, 100.0}, 2000, 1.0f);
    const float mid = 0.5f * (f.min_height + f.max_height);
    r.min_altitude_m = mid - 3.0f;
    r.max_altitude_m = mid + 3.0f;
    for (const bool poisson : {true, false}) {
        r.poisson = poisson;
        const auto p = place_population(f, r, 5);
        EXPECT_GT(p.size(), 20u);
        for (const auto& pl : p) {
            const float h = f.height_at(pl.xz.x, pl.xz.y);
            ASSERT_GE(h, r.min_altitude_m);
            ASSERT_LE(h, r.max_altitude_m);
        }
    }
}

TEST(placement_rules, density_zero_half_is_empty_and_density_one_half_is_filled) {
    const heightfield f = flat_field(100.0);
    const density_map left_empty{2, 1, {0.0f, 1.0f}};  // u < 0.5: 0 (bilinear ramps in between)
    for (const bool poisson : {true, false}) {
        SCOPED_TRACE(poisson);
        placement_rules r = rules_for({-50.0, -50.0, 50.0, 50.0}, 1000, 0.5f);
        r.poisson = poisson;
        r.density = &left_empty;
        const auto p = place_population(f, r, 3);
        std::size_t right = 0;
        for (const auto& pl : p) {
            ASSERT_GT(pl.xz.x, -25.0);  // texel 0's centre at u = 0.25: density 0 up to there
            right += pl.xz.x >= 25.0 ? 1 : 0;
        }
        if (poisson) {
            EXPECT_EQ(p.size(), 1000u);  // enough darts to fill the dense side
        } else {
            // One candidate per cell, kept with probability density: the density-1 quarter
            // (x >= 25) keeps all of its ~250 cells.
            EXPECT_NEAR(double(right), 250.0, 20.0);
        }
    }
    const density_map all_zero{1, 1, {0.0f}};
    placement_rules r = rules_for({-50.0, -50.0, 50.0, 50.0}, 100, 0.5f);
    r.density = &all_zero;
    EXPECT_TRUE(place_population(f, r, 3).empty());
}

TEST(placement_rules, jittered_grid_keeps_spacing_and_fills_about_count) {
    const heightfield f = flat_field(100.0);
    placement_rules r = rules_for({-50.0, -50.0, 50.0, 50.0}, 2500, 1.5f);
    r.poisson = false;
    const auto p = place_population(f, r, 9);
    EXPECT_EQ(p.size(), 2500u);  // 50 x 50 cells of 2 m
    for (std::size_t i = 0; i < p.size(); ++i) {
        ASSERT_GE(p[i].xz.x, -50.0);
        ASSERT_LT(p[i].xz.x, 50.0);
        for (std::size_t j = i + 1; j < p.size(); ++j)
            ASSERT_GE(glm::distance(p[i].xz, p[j].xz), 1.5 - 1e-9) << i << " " << j;
    }
    // Spacing larger than the cell: cells grow to the spacing, fewer plants.
    r.min_spacing_m = 4.0f;
    EXPECT_EQ(place_population(f, r, 9).size(), 625u);
}

TEST(placement_rules, deterministic_in_every_mode) {
    const heightfield f = generate_terrain(300.0, 65, 30.0f, 5, 0.01f, 2);
    const density_map d = procedural_density(4, 3.0f, 0.5f);
    placement_rules r = rules_for({-150.0, -150.0, 150.0, 150.0}, 3000, 2.0f);
    r.density = &d;
    r.max_slope_deg = 30.0f;
    for (const bool poisson : {true, false}) {
        r.poisson = poisson;
        const auto a = place_population(f, r, 77);
        const auto b = place_population(f, r, 77);
        const auto c = place_population(f, r, 78);
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
            EXPECT_EQ(a[i].xz, b[i].xz);
            EXPECT_EQ(a[i].seed, b[i].seed);
        }
        EXPECT_FALSE(a.size() == c.size() && a.front().xz == c.front().xz);
    }
}

TEST(placement_rules, fifty_and_hundred_thousand_plants_with_density_are_fast) {
    const heightfield f = generate_terrain(2000.0, 257, 30.0f, 5, 0.004f, 1);
    const density_map d = procedural_density(5, 4.0f, 0.7f);
    for (const std::uint32_t count : {50000u, 100000u}) {
        for (const bool poisson : {true, false}) {
            placement_rules r = rules_for({-1000.0, -1000.0, 1000.0, 1000.0}, count, 2.0f);
            r.max_slope_deg = 40.0f;
            r.density = &d;
            r.poisson = poisson;
            const auto start = std::chrono::steady_clock::now();
            const auto p = place_population(f, r, 4);
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            EXPECT_LT(seconds, 0.5);
            std::printf("[          ] %s: %zu of %u plants with density in %.1f ms\n",
                        poisson ? "poisson" : "jittered", p.size(), count, seconds * 1e3);
        }
    }
}

}  // namespace
}  // namespace sylva
