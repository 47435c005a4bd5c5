// The LoDF rung in a frame (Rebollo 2006; issue 23 item 2): a plant on it draws the full mesh's
// trunk and its foliage cluster by cluster from a slot's persistent commands; at full detail
// that is the full mesh; as the camera moves only the commands of changed clusters are uploaded;
// and the frame is the same for any thread count.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "app/scenario_player.h"
#include "gl_test_support.h"
#include "ladder_walk.h"
#include "lod/ladder.h"
#include "resources/draw_list.h"
#include "resources/lodf_slots.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

scenario tree_on(const std::vector<ladder_step_settings>& ladder, std::uint32_t frames = 4) {
    scenario s = load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "scenarios/single_tree.json");
    s.width = 240;
    s.height = 135;
    s.frames = frames;
    s.species[0].generator = "broadleaf";  // a small tree keeps the test short
    s.lod.representation = "ladder";
    s.lod.plant_budget_ms = 0.0;  // by projected size (the file ships a budget)
    s.lod.ladder = ladder;
    return s;
}

struct played {
    std::vector<frame_record> records;
    std::vector<image_rgba8> images;
};

played play(const scenario& s, int threads) {
    player_options options;
    options.id_buffer = true;
    scenario_player player(s, threads, testing::shared_gl_context(), nullptr, options);
    played out;
    for (std::uint32_t f = 0; f < s.frames; ++f) {
        out.records.push_back(player.step());
        out.images.push_back(player.capture());
    }
    return out;
}

// LoDF as the only rung is LoDF at full detail: every leaf of F_0, the full mesh's triangles,
// and its picture (the same triangles in cluster order: a pixel may differ where two leaves
// meet at one depth), shadows included: its foliage casts into the first cascade as the full
// mesh does, and each farther cascade gets the full mesh's coarser level there.
TEST(lodf_rung_gl, at_full_detail_it_draws_the_full_mesh) {
    SYLVA_REQUIRE_GL();
    const scenario lodf_only = tree_on({{"lodf"}}, 1), full_only = tree_on({{"mesh_full"}}, 1);
    ASSERT_TRUE(lodf_only.render.shadows);
    const played lodf = play(lodf_only, 2);
    const played full = play(full_only, 2);
    EXPECT_EQ(lodf.records[0].instances[std::size_t(representation::lodf)], 1u);
    EXPECT_EQ(lodf.records[0].triangles, full.records[0].triangles);
    EXPECT_EQ(lodf.records[0].shadow_triangles, full.records[0].shadow_triangles);
    const image_rgba8& a = lodf.images[0];
    const image_rgba8& b = full.images[0];
    ASSERT_EQ(a.texels.size(), b.texels.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.texels.size(); i += 4)
        differ += std::abs(int(a.texels[i]) - int(b.texels[i])) + std::abs(int(a.texels[i + 1]) - int(b.texels[i + 1])) > 8;
    EXPECT_LT(double(differ) / double(a.texels.size() / 4), 0.002) << differ << " pixels differ";
}

// Below the size where it takes over, the foliage thins with the plant's projected area; each
// frame uploads 20 bytes per cluster whose counters changed and nothing else, but for the first,
// which writes the slot's commands whole.
TEST(lodf_rung_gl, a_moving_camera_uploads_only_the_changed_clusters) {
    SYLVA_REQUIRE_GL();
    // The tree is about 100 px high: LoDF takes over at 150 px and keeps (size / 150)² of its leaves.
    const played p = play(tree_on({{"mesh_full"}, {"lodf", 150.0f, 0.0f}}, 6), 2);
    const played full = play(tree_on({{"mesh_full"}}, 1), 2);
    ASSERT_EQ(p.records[0].instances[std::size_t(representation::lodf)], 1u);
    EXPECT_LT(p.records[0].triangles, full.records[0].triangles) << "the foliage is thinned";
    EXPECT_GT(p.records[0].lodf_command_bytes, 0u);
    EXPECT_EQ(p.records[0].lodf_command_bytes % 20, 0u);
    std::uint32_t changed_frames = 0;
    for (std::size_t f = 1; f < p.records.size(); ++f) {
        EXPECT_EQ(p.records[f].lodf_command_bytes, 20u * p.records[f].lodf_changed_clusters) << "frame " << f;
        changed_frames += p.records[f].lodf_changed_clusters > 0;
    }
    EXPECT_GT(changed_frames, 0u) << "the camera moves: the detail changes";
}

// Shadows cast from the active leaves (issue 23 item 3), once: a slot's foliage casts into the
// cascades the plant overlaps when LoDF is the plant's primary rung, and is drawn in the view only
// while it is the faded partner of another rung, which casts instead (Behrendt 2005 §2.3): here
// the crossed billboard, over 120 px x (1 ± 0.2), LoDF the partner below 120 px.
TEST(lodf_rung_gl, its_foliage_casts_only_as_the_plants_primary_rung) {
    SYLVA_REQUIRE_GL();
    scenario s = tree_on({{"mesh_full"}, {"lodf", 150.0f, 0.0f}, {"crossed_billboard", 120.0f, 0.2f}}, 1);
    ASSERT_TRUE(s.render.shadows);
    testing::ladder_walk walk(s);
    constexpr std::uint32_t k_view = 1u << unsigned(render_pass::opaque);
    int primary = 0, partner = 0;
    for (const float size_px : {400.0f, 170.0f, 160.0f, 140.0f, 130.0f, 115.0f, 105.0f, 80.0f}) {
        SCOPED_TRACE(size_px);
        const testing::walk_sample sample = walk.at(walk.distance_for(size_px));
        ecs::world& world = walk.world();
        const draw_list& list = world.resource<draw_list>();
        const lod_state& lod = world.table<lod_state>().data()[0];
        if (list.lodf_plants.empty() || list.lodf_plants[0] != 0) {
            EXPECT_NE(lod.current, representation::lodf) << "on the rung without a slot";
            continue;
        }
        const std::uint32_t mask = list.lodf_pass_masks[0];
        EXPECT_TRUE(mask & k_view) << "the plant is in view";
        if (lod.current == representation::lodf) {
            ++primary;
            EXPECT_NE(mask & ~k_view, 0u) << "LoDF is the primary: its leaves cast";
        } else {
            ++partner;
            EXPECT_EQ(mask & ~k_view, 0u) << "LoDF is the partner: " << rung_name(lod.current) << " casts";
        }
    }
    EXPECT_GT(primary, 0);
    EXPECT_GT(partner, 0) << "the walk should cross the band";
}

TEST(lodf_rung_gl, the_frame_is_the_same_for_any_thread_count) {
    SYLVA_REQUIRE_GL();
    const scenario s = tree_on({{"mesh_full"}, {"lodf", 150.0f, 0.0f}}, 3);
    const played one = play(s, 1);
    const played two = play(s, 2);
    for (std::size_t f = 0; f < one.images.size(); ++f) {
        EXPECT_EQ(one.images[f].texels, two.images[f].texels) << "frame " << f;
        EXPECT_EQ(one.records[f].lodf_command_bytes, two.records[f].lodf_command_bytes) << "frame " << f;
    }
}

}  // namespace
}  // namespace sylva
