// Castaño 2010 coverage-preserving alpha mipmaps: foliage cut-outs must not thin out in the
// smaller mip levels (pure CPU functions of systems/render/textures.h; no context needed).
#include <gtest/gtest.h>

#include "systems/render/textures.h"

namespace sylva {
namespace {

// Thin vertical "needles": one opaque column in four, so plain box filtering averages alpha to
// about 0.25 and the alpha test (>= 0.5) would drop every texel from level 2 on.
image_rgba8 needles(std::uint32_t size) {
    image_rgba8 image{size, size, std::vector<std::uint8_t>(std::size_t(size) * size * 4, 60)};
    for (std::uint32_t y = 0; y < size; ++y)
        for (std::uint32_t x = 0; x < size; ++x) image.at(x, y)[3] = x % 4 == 0 ? 255 : 0;
    return image;
}

TEST(alpha_mipmaps, box_filtering_alone_loses_the_cut_out) {
    const image_rgba8 level0 = needles(64);
    EXPECT_NEAR(render::alpha_coverage(level0), 0.25f, 1e-6f);
    const image_rgba8 level2 = render::downsample(render::downsample(level0));
    EXPECT_EQ(level2.width, 16u);
    EXPECT_EQ(render::alpha_coverage(level2), 0.0f);  // averaged alpha 64 < 127.5 everywhere
}

TEST(alpha_mipmaps, rescaled_levels_keep_level_0_coverage) {
    const image_rgba8 level0 = needles(64);
    const float target = render::alpha_coverage(level0);
    image_rgba8 level = level0;
    for (int l = 1; l <= 3; ++l) {
        level = render::downsample(level);
        image_rgba8 kept = level;
        render::preserve_alpha_coverage(kept, target);
        // Level 1 is alternating 128/0 columns (reachable coverages 0 and 0.5), levels 2 and 3
        // are uniform alpha 64 (reachable 0 and 1): the smallest scale reaching the target
        // gives 0.5, then 1 -- never 0, which is what plain filtering gives.
        EXPECT_FLOAT_EQ(render::alpha_coverage(kept), l == 1 ? 0.5f : 1.0f) << "level " << l;
        EXPECT_GE(render::alpha_coverage(kept), target) << "level " << l;
    }
}

// An atlas keeps each image's coverage apart (make_texture_array's columns): rescaling columns
// [0, 4) of an 8 x 2 level whose rows read alpha 40, 80, 120, 160 there (coverage 0.25) to reach
// 0.75 takes the smallest scale passing 80 (127.5 / 80 = 1.59: 40 stays below), and leaves
// columns [4, 8) (alpha 100, passing nothing) as they were.
TEST(alpha_mipmaps, an_atlas_image_keeps_its_own_coverage) {
    image_rgba8 level{8, 2, std::vector<std::uint8_t>(8 * 2 * 4, 90)};
    for (std::uint32_t y = 0; y < 2; ++y)
        for (std::uint32_t x = 0; x < 8; ++x)
            level.at(x, y)[3] = x < 4 ? std::uint8_t(40 * (x + 1)) : 100;
    render::preserve_alpha_coverage(level, 0.75f, 0, 4);
    for (std::uint32_t y = 0; y < 2; ++y) {
        EXPECT_LT(level.at(0, y)[3], 128);
        for (std::uint32_t x = 1; x < 4; ++x) EXPECT_GE(level.at(x, y)[3], 128) << x;
        EXPECT_LE(level.at(1, y)[3], 130);  // the smallest scale that passes it
        for (std::uint32_t x = 4; x < 8; ++x) EXPECT_EQ(level.at(x, y)[3], 100) << x;
    }
}

TEST(alpha_mipmaps, downsample_is_a_2x2_box_filter) {
    image_rgba8 image{2, 2, {0, 0, 0, 0, 100, 100, 100, 100, 200, 200, 200, 200, 255, 255, 255, 255}};
    const image_rgba8 one = render::downsample(image);
    ASSERT_EQ(one.width, 1u);
    EXPECT_EQ(one.texels[0], (0 + 100 + 200 + 255 + 2) / 4);  // 139
}

TEST(alpha_mipmaps, cut_out_downsample_averages_colour_over_opaque_texels_only) {
    // Two green texels (alpha 255 and 128) beside two transparent black ones. The plain filter
    // gives (200 + 200 + 0 + 0 + 2) / 4 = 100 green; weighted by alpha the black texels count
    // for nothing: (200·255 + 200·128 + 383/2) / 383 = 200.
    image_rgba8 image{2, 2, {0, 200, 0, 255, 0, 200, 0, 128, 0, 0, 0, 0, 0, 0, 0, 0}};
    EXPECT_EQ(render::downsample(image).texels[1], 100);
    const image_rgba8 one = render::downsample_cut_out(image);
    EXPECT_EQ(one.texels[1], 200);
    EXPECT_EQ(one.texels[3], (255 + 128 + 2) / 4);  // alpha: the plain mean, 96
    // Fully transparent blocks keep the plain mean of their colour.
    image_rgba8 empty{2, 2, {40, 0, 0, 0, 80, 0, 0, 0, 40, 0, 0, 0, 80, 0, 0, 0}};
    EXPECT_EQ(render::downsample_cut_out(empty).texels[0], 60);
}

TEST(alpha_mipmaps, bleeding_fills_holes_with_the_nearest_opaque_colour) {
    // 4x4, black and transparent but for one red texel at (0, 0) and one blue at (3, 3).
    image_rgba8 image{4, 4, std::vector<std::uint8_t>(64, 0)};
    image.at(0, 0)[0] = 240, image.at(0, 0)[3] = 255;
    image.at(3, 3)[2] = 160, image.at(3, 3)[3] = 255;
    render::bleed_colour(image);
    // The 2x2 block holding the red texel turns red, the one holding the blue one blue; the
    // other two blocks take the 1x1 level's mean of the two, (120, 0, 80).
    EXPECT_EQ(image.at(1, 1)[0], 240);
    EXPECT_EQ(image.at(2, 2)[2], 160);
    EXPECT_EQ(image.at(3, 0)[0], 120);
    EXPECT_EQ(image.at(3, 0)[2], 80);
    // Alpha and the opaque texels are untouched.
    EXPECT_EQ(image.at(1, 1)[3], 0);
    EXPECT_EQ(image.at(0, 0)[0], 240);
    EXPECT_EQ(image.at(3, 3)[2], 160);
}

}  // namespace
}  // namespace sylva
