// Popping and lighting-jump scores against values worked out by hand.
#include <gtest/gtest.h>

#include "measure/image_metrics.h"
#include "measure/temporal_metrics.h"

namespace sylva {
namespace {

image_rgba8 gray(std::uint32_t w, std::uint32_t h, std::uint8_t v) {
    image_rgba8 image{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4, v)};
    for (std::size_t i = 3; i < image.texels.size(); i += 4) image.texels[i] = 255;
    return image;
}

TEST(popping_score, motion_the_reference_shows_too_cancels) {
    // Both sequences brighten by 40 everywhere: the error image stays 0.
    EXPECT_DOUBLE_EQ(popping_score(gray(4, 2, 140), gray(4, 2, 100), gray(4, 2, 140), gray(4, 2, 100)), 0.0);
    // A constant offset between test and reference is error, but not popping.
    EXPECT_DOUBLE_EQ(popping_score(gray(4, 2, 150), gray(4, 2, 150), gray(4, 2, 100), gray(4, 2, 100)), 0.0);
}

TEST(popping_score, a_switch_in_one_pixel_of_eight) {
    // Reference static at 100; the test is 100 then one pixel jumps to 200 (luma of a grey
    // pixel is its value: 0.2126 + 0.7152 + 0.0722 = 1). |E_t - E_t-1| = 100 in 1 of 8 pixels.
    image_rgba8 after = gray(4, 2, 100);
    after.at(1, 1)[0] = after.at(1, 1)[1] = after.at(1, 1)[2] = 200;
    EXPECT_NEAR(popping_score(after, gray(4, 2, 100), gray(4, 2, 100), gray(4, 2, 100)), 12.5, 1e-12);
}

TEST(popping_score, luma_weights_a_green_change_most) {
    // One pure-green change of 255 in a single-pixel image: 0.7152 * 255 = 182.376.
    image_rgba8 before = gray(1, 1, 0);
    image_rgba8 after = before;
    after.texels[1] = 255;
    EXPECT_NEAR(popping_score(after, before, before, before), 182.376, 1e-9);
}

TEST(popping_score, rejects_different_sizes) {
    EXPECT_THROW(popping_score(gray(4, 2, 0), gray(4, 2, 0), gray(2, 4, 0), gray(4, 2, 0)), std::invalid_argument);
}

TEST(mean_plant_colors, averages_each_id_and_skips_zero) {
    image_rgba8 image = gray(3, 1, 0);
    const std::uint8_t colors[3][3] = {{10, 20, 30}, {30, 40, 50}, {255, 255, 255}};
    for (std::uint32_t x = 0; x < 3; ++x)
        for (int c = 0; c < 3; ++c) image.at(x, 0)[c] = colors[x][c];
    const plant_colors result = mean_plant_colors(image, {7, 7, 0});
    ASSERT_EQ(result.size(), 1u);
    const plant_color& c = result.at(7);
    EXPECT_EQ(c.pixels, 2u);
    EXPECT_DOUBLE_EQ(c.r, 20.0);
    EXPECT_DOUBLE_EQ(c.g, 30.0);
    EXPECT_DOUBLE_EQ(c.b, 40.0);
    EXPECT_THROW(mean_plant_colors(image, {1, 2}), std::invalid_argument);
}

TEST(lighting_jump, is_the_change_beyond_the_reference_change) {
    // Test goes (100,100,100) -> (130,140,100): change (30,40,0). The reference goes
    // (90,90,90) -> (90,90,90): no change. Jump = |(30,40,0)| = 50.
    const plant_color before{100, 100, 100, 10}, after{130, 140, 100, 10}, reference{90, 90, 90, 10};
    EXPECT_DOUBLE_EQ(lighting_jump(before, after, reference, reference), 50.0);
    // If the reference brightens the same way (the sun came out), there is no jump.
    const plant_color reference_after{120, 130, 90, 10};
    EXPECT_DOUBLE_EQ(lighting_jump(before, after, reference, reference_after), 0.0);
}

TEST(plant_mask, marks_nonzero_ids) {
    const std::vector<std::uint8_t> expected{0, 1, 1, 0};
    EXPECT_EQ(plant_mask({0, 3, 1, 0}), expected);
    EXPECT_DOUBLE_EQ(coverage_iou(plant_mask({0, 3, 1, 0}), plant_mask({0, 9, 0, 2})), 1.0 / 3.0);
}

}  // namespace
}  // namespace sylva
