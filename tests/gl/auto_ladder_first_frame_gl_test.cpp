// The auto ladder's first frame (app/scenario_player.h step): the budget solver weighs each plant
// by what the frame before showed of it, and before a run's first frame none did. That frame is
// rehearsed (drawn, not shown) so its choice already sees which plants hide behind others, and
// nothing dissolves from the rehearsal's rungs; a player rewound by the bench forgets the frame
// it showed, so its frames are a fresh player's.
#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <vector>

#include "app/scenario_player.h"
#include "components/lod_state.h"
#include "models/cache/bake_cache.h"
#include "models/image/image.h"
#include "scenarios/scenario_loader.h"
#include "systems/render/gl_context.h"

namespace sylva {
namespace {

// default's own auto ladder, small.
scenario auto_default() {
    scenario s = load_bundled_scenario("default");
    s.width = 160;
    s.height = 90;
    s.frames = 3;
    s.lod.representation = "ladder";
    s.lod.plant_budget_ms = 60.0;
    return s;
}

std::unique_ptr<render::gl_context> context_for(const scenario& s) {
    render::context_options options;
    options.width = int(s.width);
    options.height = int(s.height);
    options.headless = true;
    return render::create_context(options);
}

// The rung of every plant in the player's last frame.
std::vector<representation> rungs_of(scenario_player& player) {
    const auto& lod = player.world().table<lod_state>();
    std::vector<representation> rungs;
    for (std::size_t i = 0; i < lod.size(); ++i) rungs.push_back(lod.data()[i].current);
    return rungs;
}

TEST(auto_ladder_first_frame, the_second_frame_keeps_the_rungs_the_first_chose) {
    const scenario s = auto_default();
    std::unique_ptr<render::gl_context> context;
    try {
        context = context_for(s);
    } catch (const std::exception& e) {
        GTEST_SKIP() << "no GL 4.5 context (OSMesa): " << e.what();
    }
    bake_cache cache;  // $SYLVA_CACHE_DIR or the user's: the tables are default's own
    scenario_player player(s, 2, context.get(), &cache);
    player.step();
    const std::vector<representation> first = rungs_of(player);
    player.step();
    const std::vector<representation> second = rungs_of(player);
    std::size_t drawn = 0, changed = 0;
    for (std::size_t i = 0; i < first.size(); ++i) {
        drawn += first[i] != representation::none;
        changed += first[i] != representation::none && second[i] != first[i];
    }
    ASSERT_GT(drawn, 100u);
    // Judged wholly seen, the first frame bought dearer rungs for hidden plants that the second,
    // seeing them hidden, took back, dissolving them for fade_frames frames: without the rehearsal
    // 2,010 of 6,997 plants changed rung from frame 0 to 1, with it 285 (the camera moves).
    EXPECT_LE(changed, drawn / 10)
        << changed << " of " << drawn << " plants changed rung from frame 0 to 1";
}

TEST(auto_ladder_first_frame, a_rewound_player_that_forgets_plays_a_fresh_player_s_frames) {
    scenario s = auto_default();
    std::unique_ptr<render::gl_context> context;
    try {
        context = context_for(s);
    } catch (const std::exception& e) {
        GTEST_SKIP() << "no GL 4.5 context (OSMesa): " << e.what();
    }
    bake_cache cache;
    std::vector<image_rgba8> fresh;
    {
        scenario_player player(s, 2, context.get(), &cache);
        for (std::uint32_t f = 0; f < s.frames; ++f) {
            player.step();
            fresh.push_back(player.capture());
        }
    }
    scenario_player player(s, 2, context.get(), &cache);
    for (std::uint32_t f = 0; f < s.frames; ++f) player.step();
    player.set_frame(0);
    player.forget_shown_frame();
    for (std::uint32_t f = 0; f < s.frames; ++f) {
        player.step();
        EXPECT_TRUE(player.capture().texels == fresh[f].texels)
            << "frame " << f << " differs from a fresh player's";
    }
}

}  // namespace
}  // namespace sylva
