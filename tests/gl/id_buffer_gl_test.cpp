// The ID buffer (measurement): writing plant IDs must not change the image, every ID must name a
// plant the cull system found visible, and sky pixels carry no ID.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "app/scenario_player.h"
#include "components/lod_state.h"
#include "gl_test_support.h"
#include "scenarios/scenario_loader.h"
#include "tests/tiny_scene.h"

namespace sylva {
namespace {

scenario tiny() {
    return testing::tiny_with_mesh_levels();
}

TEST(id_buffer, names_visible_plants_and_leaves_the_image_unchanged) {
    SYLVA_REQUIRE_GL();
    auto* context = testing::shared_gl_context();
    scenario_player plain(tiny(), 2, context);
    player_options options;
    options.id_buffer = true;
    scenario_player measured(tiny(), 2, context, nullptr, options);
    for (int f = 0; f < 2; ++f) {
        plain.step();
        measured.step();
    }
    const image_rgba8 a = plain.capture();
    const image_rgba8 b = measured.capture();
    ASSERT_EQ(a.texels.size(), b.texels.size());
    EXPECT_EQ(a.texels, b.texels) << "writing IDs changed the colour image";
    EXPECT_TRUE(plain.capture_plant_ids().empty());

    const std::vector<std::uint32_t> ids = measured.capture_plant_ids();
    ASSERT_EQ(ids.size(), std::size_t(b.width) * b.height);
    const auto& lod = measured.world().table<lod_state>();
    std::set<std::uint32_t> seen;
    std::size_t covered = 0;
    for (std::uint32_t id : ids) {
        if (id == 0) continue;
        ++covered;
        seen.insert(id);
        ASSERT_LE(id, lod.size());
        EXPECT_EQ(lod.data()[id - 1].visible, 1) << "plant " << id - 1 << " has pixels but was culled";
    }
    EXPECT_GT(seen.size(), 3u);
    EXPECT_GT(covered, ids.size() / 50);
    EXPECT_LT(covered, ids.size());
}

TEST(id_buffer, supersampled_ids_take_each_blocks_centre_sample) {
    SYLVA_REQUIRE_GL();
    scenario s = tiny();
    player_options options;
    options.id_buffer = true;
    scenario_player single(s, 1, testing::shared_gl_context(), nullptr, options);
    s.width *= 3;
    s.height *= 3;
    scenario_player triple(s, 1, testing::shared_gl_context(), nullptr, options);
    single.step();
    triple.step();
    const auto a = single.capture_plant_ids();
    const auto b = triple.capture_plant_ids(3);
    const auto full = triple.capture_plant_ids(1);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(full.size(), 9 * b.size());
    // Exactly the centre sample of each 3x3 block.
    const std::size_t w = single.settings().width;
    for (std::size_t i = 0; i < b.size(); ++i) {
        const std::size_t x = i % w, y = i / w;
        ASSERT_EQ(b[i], full[(3 * y + 1) * 3 * w + 3 * x + 1]) << "pixel " << x << "," << y;
    }
    // And that sample lies on the 1x pixel's centre, so the IDs mostly agree with the 1x frame;
    // they differ where leaves are alpha-tested at another mip level and on silhouette edges.
    std::size_t same = 0;
    for (std::size_t i = 0; i < a.size(); ++i) same += a[i] == b[i] ? 1 : 0;
    EXPECT_GT(double(same) / double(a.size()), 0.9);
}

}  // namespace
}  // namespace sylva
