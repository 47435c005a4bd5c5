// The view's rung colours (app/rung_colours.h) on a hand-made frame: a plant pixel takes its
// plant's rung colour scaled by the pixel's brightness, everything else is dimmed.
#include "app/rung_colours.h"

#include <gtest/gtest.h>

namespace sylva {
namespace {

TEST(rung_colours, plant_pixels_take_their_rung_colour_and_the_rest_is_dimmed) {
    image_rgba8 frame;
    frame.width = 3;
    frame.height = 1;
    frame.texels = {255, 255, 255, 255, 0, 0, 0, 255, 100, 120, 140, 255};
    const std::vector<std::uint32_t> ids{1, 2, 0};  // plant 0, plant 1, sky
    std::vector<lod_state> lods(2);
    lods[0].current = representation::billboard_cloud;
    lods[1].current = representation::mesh_full;
    const image_rgba8 out = tint_by_rung(frame, ids, lods);
    // White (luma 255): the whole colour, (102 + 153) / 255 = 1. The cloud's key is (60, 200, 90).
    EXPECT_EQ(out.texels[0], 60);
    EXPECT_EQ(out.texels[1], 200);
    EXPECT_EQ(out.texels[2], 90);
    // Black (luma 0): 102 / 255 = 0.4 of mesh_full's (230, 60, 50): 92, 24, 20.
    EXPECT_EQ(out.texels[4], 92);
    EXPECT_EQ(out.texels[5], 24);
    EXPECT_EQ(out.texels[6], 20);
    // The sky at half its brightness, alpha kept.
    EXPECT_EQ(out.texels[8], 50);
    EXPECT_EQ(out.texels[9], 60);
    EXPECT_EQ(out.texels[10], 70);
    EXPECT_EQ(out.texels[11], 255);
}

TEST(rung_colours, every_rung_of_a_ladder_has_its_own_colour) {
    for (std::size_t i = 0; i < k_rung_colours.size(); ++i)
        for (std::size_t j = 0; j < i; ++j) EXPECT_NE(k_rung_colours[i].rgb, k_rung_colours[j].rgb);
}

}  // namespace
}  // namespace sylva
