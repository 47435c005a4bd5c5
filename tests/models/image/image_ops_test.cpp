#include "models/image/image_ops.h"

#include <gtest/gtest.h>

namespace sylva {
namespace {

TEST(box_downsample, averages_each_block_with_rounding) {
    // 3x3 block of values 0..8 in red: mean 4; green all 10; blue 0 and 255 alternating (5x255/9=141.7 -> 142).
    image_rgba8 image{3, 3, std::vector<std::uint8_t>(36, 0)};
    for (std::uint32_t i = 0; i < 9; ++i) {
        image.texels[i * 4 + 0] = std::uint8_t(i);
        image.texels[i * 4 + 1] = 10;
        image.texels[i * 4 + 2] = i % 2 == 0 ? 255 : 0;
        image.texels[i * 4 + 3] = 255;
    }
    const image_rgba8 out = box_downsample(image, 3);
    ASSERT_EQ(out.width, 1u);
    EXPECT_EQ(out.texels[0], 4);
    EXPECT_EQ(out.texels[1], 10);
    EXPECT_EQ(out.texels[2], 142);
    EXPECT_EQ(out.texels[3], 255);
}

TEST(box_downsample, rejects_sizes_that_are_not_multiples) {
    image_rgba8 image{4, 3, std::vector<std::uint8_t>(48, 0)};
    EXPECT_THROW(box_downsample(image, 3), std::invalid_argument);
    EXPECT_NO_THROW(box_downsample(image, 1));
}

}  // namespace
}  // namespace sylva
