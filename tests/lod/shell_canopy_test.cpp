// The sunlight through the slices above (lod/shell_canopy.h): T_k = Π_{j > k} (1 − α_j).
#include "lod/shell_canopy.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace sylva {
namespace {

image_rgba8 one_texel(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) {
    image_rgba8 i;
    i.width = 1;
    i.height = 1;
    i.texels = {r, g, b, a};
    return i;
}

// Three slices, bottom first, alpha 0 (bottom), 64 and 128 (top); by hand: the top sees the sky
// (255), the middle 1 − 128/255 = 0.498 → 127, the bottom 0.498 · (1 − 64/255) = 0.373 → 95.
TEST(shell_canopy, each_slice_gets_the_transmittance_of_the_slices_above) {
    const std::vector<image_rgba8> colour = {one_texel(0, 0, 0, 0), one_texel(10, 20, 30, 64), one_texel(40, 50, 60, 128)};
    const std::vector<image_rgba8> normal = {one_texel(128, 255, 128, 0), one_texel(100, 200, 150, 64),
                                             one_texel(90, 210, 120, 128)};
    const std::vector<image_rgba8> lit = with_canopy_transmittance(normal, colour);
    ASSERT_EQ(lit.size(), 3u);
    EXPECT_EQ(lit[2].texels[3], 255);
    EXPECT_EQ(lit[1].texels[3], 127);
    EXPECT_EQ(lit[0].texels[3], 95);
    // The normals themselves stay.
    for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(lit[k].texels[c], normal[k].texels[c]) << k << " " << c;
}

// An opaque slice shades everything below it whatever lies between.
TEST(shell_canopy, an_opaque_slice_leaves_no_sun_below_it) {
    const std::vector<image_rgba8> colour = {one_texel(0, 0, 0, 10), one_texel(0, 0, 0, 255), one_texel(0, 0, 0, 0)};
    const std::vector<image_rgba8> lit = with_canopy_transmittance(colour, colour);
    EXPECT_EQ(lit[2].texels[3], 255);
    EXPECT_EQ(lit[1].texels[3], 255);
    EXPECT_EQ(lit[0].texels[3], 0);
}

TEST(shell_canopy, mismatched_slices_are_refused) {
    const std::vector<image_rgba8> two = {one_texel(0, 0, 0, 0), one_texel(0, 0, 0, 0)};
    const std::vector<image_rgba8> one = {one_texel(0, 0, 0, 0)};
    EXPECT_THROW(with_canopy_transmittance(two, one), std::invalid_argument);
    image_rgba8 wide = one_texel(0, 0, 0, 0);
    wide.width = 2;
    wide.texels.resize(8);
    EXPECT_THROW(with_canopy_transmittance({wide}, one), std::invalid_argument);
}

}  // namespace
}  // namespace sylva
