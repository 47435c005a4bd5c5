// The viewer's tuning loop without the window (app/implicit_tuning.h): a species re-baked in the
// background with a lower k_a,min reports its progress to the end, and a player built on those
// assets (as `sylva view` swaps it in) draws the crown darker than before.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/implicit_tuning.h"
#include "gl_test_support.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

double mean_plant_luma(scenario_player& player) {
    const image_rgba8 image = player.capture();
    const std::vector<std::uint32_t> ids = player.capture_plant_ids();
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < ids.size(); ++i)
        if (ids[i] != 0) {
            const std::uint8_t* p = &image.texels[4 * i];
            sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            ++n;
        }
    EXPECT_GT(n, 1000u);
    return sum / double(std::max<std::size_t>(n, 1));
}

TEST(implicit_tuning_gl, a_background_rebake_swaps_in_a_darker_crown) {
    SYLVA_REQUIRE_GL();
    scenario s = load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "scenarios/single_tree.json");
    s.width = 240;
    s.height = 135;
    s.lod.lighting = "implicit";
    s.lod.representation = "mesh_levels";  // the file's auto ladder would measure rung tables first
    s.lod.plant_budget_ms = 0.0;
    s.species[0].implicit.generator_fraction = 0.1f;
    player_options options;
    options.id_buffer = true;
    scenario_player before(s, 2, testing::shared_gl_context(), nullptr, options);
    before.step();
    const double luma_before = mean_plant_luma(before);

    implicit_lighting_settings tuned = s.species[0].implicit;
    tuned.ka_min = 0.05f;  // the default is 0.3
    implicit_rebake rebake(before.settings(), 0, tuned, options, std::nullopt);
    float last = 0.0f;
    while (!rebake.ready()) {
        EXPECT_GE(rebake.progress(), last);  // progress only moves forward
        last = rebake.progress();
    }
    EXPECT_EQ(rebake.progress(), 1.0f);
    player_options swapped = options;
    swapped.assets = rebake.take();
    scenario_player after(rebake.tuned(), 2, testing::shared_gl_context(), nullptr, swapped);
    after.step();
    const double luma_after = mean_plant_luma(after);
    std::printf("crown luma %.1f -> %.1f with k_a,min 0.3 -> 0.05\n", luma_before, luma_after);
    EXPECT_LT(luma_after, luma_before - 2.0);
    EXPECT_EQ(after.settings().species[0].implicit.ka_min, 0.05f);
}

}  // namespace
}  // namespace sylva
