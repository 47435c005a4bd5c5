// Numerical stress: the same scene placed 1e4, 1e5 and 1e6 m from the origin renders like the
// scene at the origin. Positions are double precision and rendering is camera-relative, so
// only the shadow texel grid (pinned to the world, so its phase moves with the offset) may
// differ a little. Tolerance: PSNR above 45 dB and under 1 % of pixels off by more than 16.
#include <gtest/gtest.h>

#include <filesystem>

#include "../gl/gl_test_support.h"
#include "../golden/golden_support.h"
#include "app/scenario_player.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

image_rgba8 render_at(double offset, render::gl_context& context) {
    scenario s = load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "scenarios/tiny.json");
    s.world_offset = {offset, 0.0, offset};
    scenario_player player(s, 2, &context);
    player.step();
    player.step();
    return player.capture();
}

TEST(world_offset, scenes_far_from_the_origin_render_like_the_origin) {
    SYLVA_REQUIRE_GL();
    render::context_options options;
    options.width = 160;
    options.height = 90;
    auto context = render::create_context(options);
    const image_rgba8 origin = render_at(0.0, *context);
    for (double offset : {1e4, 1e5, 1e6}) {
        const auto d = testing::compare_images(origin, render_at(offset, *context));
        EXPECT_GT(d.psnr_db, 45.0) << "offset " << offset;
        EXPECT_LT(d.fraction_over_16, 0.01) << "offset " << offset;
    }
}

}  // namespace
}  // namespace sylva
