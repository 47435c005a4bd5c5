// Golden image of the small `tiny` scenario (mesh levels), rendered headless on OSMesa. The
// committed golden is tests/golden/data/tiny_frame_0003.png; SYLVA_UPDATE_GOLDEN=1 rewrites it
// after an intended change (look at the new image before committing it).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "../gl/gl_test_support.h"
#include "golden_support.h"
#include "tests/tiny_scene.h"

namespace sylva {
namespace {

scenario tiny() {
    return testing::tiny_with_mesh_levels();
}

TEST(golden, tiny_scenario_frame_3_matches_the_committed_image) {
    SYLVA_REQUIRE_GL();
    testing::expect_matches_golden(testing::render_frame(tiny(), 3).image, "tiny_frame_0003.png");
}

TEST(golden, the_frame_is_a_lit_landscape_not_a_blank_image) {
    SYLVA_REQUIRE_GL();
    const image_rgba8 image = testing::render_frame(tiny(), 0).image;
    // Sky at the top (bluish, bright), darker vegetation and ground lower down, many colours.
    double top_blue = 0.0, bottom_luma = 0.0, top_luma = 0.0;
    const std::uint32_t w = image.width, h = image.height;
    for (std::uint32_t x = 0; x < w; ++x) {
        const auto* top = image.at(x, 1);
        const auto* bottom = image.at(x, h - 2);
        top_blue += double(top[2]) - double(top[0]);
        top_luma += 0.3 * top[0] + 0.59 * top[1] + 0.11 * top[2];
        bottom_luma += 0.3 * bottom[0] + 0.59 * bottom[1] + 0.11 * bottom[2];
    }
    EXPECT_GT(top_blue / w, 10.0);
    EXPECT_GT(top_luma, bottom_luma);
    std::set<std::uint32_t> colours;
    for (std::size_t p = 0; p < image.texels.size(); p += 4)
        colours.insert(std::uint32_t(image.texels[p]) << 16 |
                       std::uint32_t(image.texels[p + 1]) << 8 | image.texels[p + 2]);
    EXPECT_GT(colours.size(), 500u);
}

}  // namespace
}  // namespace sylva
