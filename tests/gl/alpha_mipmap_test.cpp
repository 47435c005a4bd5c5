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

TEST(alpha_mipmaps, downsample_is_a_2x2_box_filter) {
    image_rgba8 image{2, 2, {0, 0, 0, 0, 100, 100, 100, 100, 200, 200, 200, 200, 255, 255, 255, 255}};
    const image_rgba8 one = render::downsample(image);
    ASSERT_EQ(one.width, 1u);
    EXPECT_EQ(one.texels[0], (0 + 100 + 200 + 255 + 2) / 4);  // 139
}

}  // namespace
}  // namespace sylva
