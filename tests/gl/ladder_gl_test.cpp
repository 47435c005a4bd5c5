// The representation ladder (DESIGN §1.5) drawn by the GL renderer: the tree of
// scenarios/single_tree.json walks down a ladder through every handover a ladder can make
// between the papers' rungs (full mesh -> billboard cloud -> points and lines -> crossed
// billboard) as the camera backs away, and across no band does the plant thin out: its ID-buffer
// coverage, times distance² (what a fixed shape keeps as it recedes), never falls far below what
// the rungs on either side of the band cover whole.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/scenario_player.h"
#include "components/transform.h"
#include "gl_test_support.h"
#include "ladder_walk.h"
#include "lod/ladder.h"
#include "lod/point_line_lod.h"
#include "measure/temporal_metrics.h"
#include "resources/playback.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_width = 480;
constexpr std::uint32_t k_height = 270;

struct step {
    const char* rung;
    float below_px;
};
// Switch sizes far enough apart that the ±15 % bands leave each rung a stretch of its own.
constexpr std::array<step, 4> k_steps{{{"mesh_full", 0.0f},
                                       {"billboard_cloud", 150.0f},
                                       {"points_lines", 60.0f},
                                       {"crossed_billboard", 25.0f}}};

scenario tree_on_a_ladder() {
    scenario s = load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "scenarios/single_tree.json");
    s.width = k_width;
    s.height = k_height;
    s.lod.representation = "ladder";
    s.lod.plant_budget_ms = 0.0;  // by projected size (the file ships a budget)
    s.lod.ladder.clear();
    for (const step& st : k_steps) s.lod.ladder.push_back({st.rung, st.below_px, k_default_band});
    return s;
}

using testing::drawn;
using testing::walk_sample;

class walk_down_the_ladder : public ::testing::Test {
protected:
    walk_down_the_ladder() : m_walk(tree_on_a_ladder()) {}
    double distance_for(float size_px) { return m_walk.distance_for(size_px); }
    walk_sample at(double distance_m) { return m_walk.at(distance_m); }
    testing::ladder_walk m_walk;
};

TEST_F(walk_down_the_ladder, no_handover_thins_the_plant_out) {
    SYLVA_REQUIRE_GL();
    for (std::size_t i = 1; i < k_steps.size(); ++i) {
        const representation nearer = *rung_of_name(k_steps[i - 1].rung);
        const representation farther = *rung_of_name(k_steps[i].rung);
        SCOPED_TRACE(std::string(k_steps[i - 1].rung) + " -> " + k_steps[i].rung);
        const float s = k_steps[i].below_px, h = k_default_band;
        // Just outside the band on each side: one rung whole.
        const walk_sample before = at(distance_for(s * (1.0f + h) * 1.02f));
        const walk_sample after = at(distance_for(s * (1.0f - h) * 0.98f));
        EXPECT_GT(drawn(before, nearer), 0u);
        EXPECT_EQ(drawn(before, farther), 0u);
        EXPECT_GT(drawn(after, farther), 0u);
        EXPECT_EQ(drawn(after, nearer), 0u);
        const double floor = 0.85 * std::min(before.normalised(), after.normalised());
        ASSERT_GT(before.pixels, 100u);
        std::printf("%s -> %s: coverage x d² at the edges %.0f, %.0f; inside:", k_steps[i - 1].rung, k_steps[i].rung,
                    before.normalised(), after.normalised());
        for (int k = 1; k < 10; ++k) {
            const float size = s * (1.0f + h - 2.0f * h * float(k) / 10.0f);
            const walk_sample in = at(distance_for(size));
            std::printf(" %.0f", in.normalised());
            EXPECT_GE(in.normalised(), floor) << "at " << size << " px (" << in.distance_m << " m)";
            // Inside the band both rungs are drawn: the one fading is the partner.
            EXPECT_GT(drawn(in, nearer), 0u) << "at " << size << " px";
            EXPECT_GT(drawn(in, farther), 0u) << "at " << size << " px";
        }
        std::printf("\n");
    }
}

}  // namespace
}  // namespace sylva
