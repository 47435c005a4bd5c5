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
#include "components/bounds.h"
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

// The oak's pixels in the ID buffer seen from `azimuth_deg` around it, level, 40 m away (or
// from `elevation_deg` above its middle, looking at the middle).
class orbit {
public:
    explicit orbit(const char* rung)
        : m_player(oak_on({{rung, 0.0f, k_default_band}}), 2, testing::shared_gl_context(), nullptr, id_buffer()) {}

    struct seen {
        double pixels = 0.0;
        double fragments = 0.0;  // fragment shader invocations of the frame (0: not counted)
        std::vector<bool> mask;  // the oak's pixels
    };
    seen at(double azimuth_deg) { return from(azimuth_deg, glm::dvec3(0.0, 6.0, 0.0), 0.0); }
    seen at(double azimuth_deg, double elevation_deg) {
        const double middle = double(m_player.world().table<bounds>().data()[0].center_height);
        return from(azimuth_deg, glm::dvec3(0.0, middle, 0.0), elevation_deg);
    }

private:
    seen from(double azimuth_deg, glm::dvec3 target, double elevation_deg) {
        ecs::world& world = m_player.world();
        const world_transform& oak = world.table<world_transform>().data()[0];
        const glm::dvec3 base = oak.position;
        const double a = azimuth_deg * M_PI / 180.0 + double(oak.yaw);
        const double e = elevation_deg * M_PI / 180.0;
        camera_keyframe key;
        key.position =
            base + target +
            40.0 * glm::dvec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
        key.target = base + target;
        key.fov_deg = 50.0f;
        world.resource<camera_track>().keys = {key};
        m_player.set_frame(0);
        const frame_record record = m_player.step();
        const std::vector<std::uint32_t> ids = m_player.capture_plant_ids();
        seen out;
        out.mask.resize(ids.size());
        for (std::size_t i = 0; i < ids.size(); ++i) out.mask[i] = ids[i] != 0;
        out.pixels = double(std::count(out.mask.begin(), out.mask.end(), true));
        out.fragments = double(record.fragments);
        return out;
    }

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

double iou(const std::vector<bool>& a, const std::vector<bool>& b) {
    std::size_t both = 0, either = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
        both += a[i] && b[i];
        either += a[i] || b[i];
    }
    return either ? double(both) / double(either) : 0.0;
}

// Seen from above, the facing billboard tilts back to its nearest baked elevation and shows the
// crown from there, so its silhouette follows the full mesh's; the crossed pair shows its level
// views foreshortened. At eye level both show the same (the level views). (IoU with the mesh at
// 0 / 16 / 30 degrees: facing 0.938 / 0.930 / 0.918, crossed 0.939 / 0.917 / 0.853; with the
// quad tilted about the plant's foot instead of its middle, so that in perspective it stood
// farther than the crown, facing 0.872 at 16 degrees.)
TEST(facing_billboard, seen_from_above_shows_the_view_from_its_elevation) {
    SYLVA_REQUIRE_GL();
    orbit full("mesh_full");
    orbit facing("facing_billboard");
    orbit crossed("crossed_billboard");
    for (const double elevation : {0.0, 16.0, 30.0}) {
        const orbit::seen m = full.at(0.0, elevation), f = facing.at(0.0, elevation),
                          c = crossed.at(0.0, elevation);
        const double facing_iou = iou(f.mask, m.mask), crossed_iou = iou(c.mask, m.mask);
        std::printf(
            "elevation %4.1f deg: IoU with the full mesh facing %.4f crossed %.4f (%.0f / %.0f / "
            "%.0f px)\n",
            elevation, facing_iou, crossed_iou, m.pixels, f.pixels, c.pixels);
        ASSERT_GT(m.pixels, 1000.0);
        if (elevation == 0.0)
            EXPECT_NEAR(facing_iou, crossed_iou, 0.02);
        else
            EXPECT_GT(facing_iou, crossed_iou + 0.01) << "at " << elevation << " deg";
    }
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
