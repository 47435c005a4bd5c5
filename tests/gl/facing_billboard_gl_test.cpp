// The facing billboard (representation::facing_billboard): the crossed billboard with the quad
// whose baked view is nearer the eye's turned to face it, the other collapsed (shaders/
// instance.glsl face_the_eye). Drawn by the GL renderer around the oak of
// scenarios/single_tree.json: from every azimuth it covers what the crossed pair covers seen
// face-on to the quad it shows, where the pair seen between its quads foreshortens both (the
// plant looks thinner) and shades both; and the handover from the crossed billboard into it does
// not thin the plant out.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/scenario_player.h"
#include "components/transform.h"
#include "gl_test_support.h"
#include "ladder_walk.h"
#include "lod/ladder.h"
#include "resources/playback.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_width = 320;
constexpr std::uint32_t k_height = 240;

scenario oak_on(std::vector<ladder_step_settings> ladder) {
    scenario s = load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "scenarios/single_tree.json");
    s.width = k_width;
    s.height = k_height;
    s.lod.representation = "ladder";
    s.lod.plant_budget_ms = 0.0;  // by projected size (the file ships a budget)
    s.lod.ladder = std::move(ladder);
    return s;
}

// The oak's pixels in the ID buffer seen from `azimuth_deg` around it, level, 40 m away.
class orbit {
public:
    explicit orbit(const char* rung)
        : m_player(oak_on({{rung, 0.0f, k_default_band}}), 2, testing::shared_gl_context(), nullptr, id_buffer()) {}

    struct seen {
        double pixels = 0.0;
        double fragments = 0.0;  // fragment shader invocations of the frame (0: not counted)
    };
    seen at(double azimuth_deg) {
        ecs::world& world = m_player.world();
        const world_transform& oak = world.table<world_transform>().data()[0];
        const glm::dvec3 base = oak.position;
        const double a = azimuth_deg * M_PI / 180.0 + double(oak.yaw);
        camera_keyframe key;
        key.position = base + glm::dvec3(40.0 * std::sin(a), 6.0, 40.0 * std::cos(a));
        key.target = base + glm::dvec3(0.0, 6.0, 0.0);
        key.fov_deg = 50.0f;
        world.resource<camera_track>().keys = {key};
        m_player.set_frame(0);
        const frame_record record = m_player.step();
        const std::vector<std::uint32_t> ids = m_player.capture_plant_ids();
        return {double(std::count_if(ids.begin(), ids.end(), [](std::uint32_t id) { return id != 0; })),
                double(record.fragments)};
    }

private:
    static player_options id_buffer() {
        player_options options;
        options.id_buffer = true;
        return options;
    }
    scenario_player m_player;
};

constexpr std::array<double, 6> k_azimuths{0.0, 30.0, 45.0, 60.0, 90.0, 180.0};

TEST(facing_billboard, shows_the_nearer_quad_face_on_where_the_crossed_pair_thins) {
    SYLVA_REQUIRE_GL();
    orbit facing("facing_billboard");
    orbit crossed("crossed_billboard");
    std::array<orbit::seen, k_azimuths.size()> f{}, c{};
    for (std::size_t i = 0; i < k_azimuths.size(); ++i) {
        f[i] = facing.at(k_azimuths[i]);
        c[i] = crossed.at(k_azimuths[i]);
        std::printf("azimuth %5.1f deg: facing %.0f px %.0f fragments, crossed %.0f px %.0f fragments\n",
                    k_azimuths[i], f[i].pixels, f[i].fragments, c[i].pixels, c[i].fragments);
    }
    ASSERT_GT(f[0].pixels, 1000.0);
    // Face-on to a quad (0, 90 and, from behind, 180 degrees) the two draw that quad's image over
    // the other's edge.
    EXPECT_NEAR(f[0].pixels / c[0].pixels, 1.0, 0.02);
    EXPECT_NEAR(f[4].pixels / c[4].pixels, 1.0, 0.02);
    EXPECT_NEAR(f[5].pixels / c[5].pixels, 1.0, 0.02);
    // Within 45 degrees of a quad's view the facing billboard shows that quad face-on.
    EXPECT_NEAR(f[1].pixels / f[0].pixels, 1.0, 0.02);
    EXPECT_NEAR(f[2].pixels / f[0].pixels, 1.0, 0.02);
    EXPECT_NEAR(f[3].pixels / f[4].pixels, 1.0, 0.02);
    // Between its quads the crossed pair foreshortens both: the plant looks thinner, and both
    // quads shade fragments.
    EXPECT_LT(c[2].pixels / c[0].pixels, 0.92);
    if (c[2].fragments > 0.0) EXPECT_LT(f[2].fragments, c[2].fragments);
}

// Across the band from the crossed billboard into the facing one the oak keeps its coverage
// (times distance², as tests/gl/ladder_gl_test.cpp judges every other handover).
TEST(facing_billboard, takes_over_from_the_crossed_billboard_without_thinning_the_plant) {
    SYLVA_REQUIRE_GL();
    constexpr float k_switch_px = 80.0f;
    testing::ladder_walk walk(oak_on({{"crossed_billboard", 0.0f, k_default_band},
                                      {"facing_billboard", k_switch_px, k_default_band}}));
    const float h = k_default_band;
    const testing::walk_sample before = walk.at(walk.distance_for(k_switch_px * (1.0f + h) * 1.02f));
    const testing::walk_sample after = walk.at(walk.distance_for(k_switch_px * (1.0f - h) * 0.98f));
    EXPECT_GT(testing::drawn(before, representation::crossed_billboard), 0u);
    EXPECT_EQ(testing::drawn(before, representation::facing_billboard), 0u);
    EXPECT_GT(testing::drawn(after, representation::facing_billboard), 0u);
    EXPECT_EQ(testing::drawn(after, representation::crossed_billboard), 0u);
    ASSERT_GT(before.pixels, 100u);
    const double floor = 0.85 * std::min(before.normalised(), after.normalised());
    for (int k = 1; k < 10; ++k) {
        const float size = k_switch_px * (1.0f + h - 2.0f * h * float(k) / 10.0f);
        const testing::walk_sample in = walk.at(walk.distance_for(size));
        EXPECT_GE(in.normalised(), floor) << "at " << size << " px";
        EXPECT_GT(testing::drawn(in, representation::crossed_billboard), 0u) << "at " << size << " px";
        EXPECT_GT(testing::drawn(in, representation::facing_billboard), 0u) << "at " << size << " px";
    }
}

}  // namespace
}  // namespace sylva
