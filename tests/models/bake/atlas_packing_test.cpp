// Atlas packing for billboard clouds: no two rectangles overlap or come closer than the gutter,
// hand-counted tight fits, refusal when they cannot fit, and a placement of equal-sized
// rectangles that does not depend on the C library's qsort.
#include "models/bake/atlas_packing.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "models/random.h"

namespace sylva {
namespace {

atlas_rect grown(const atlas_rect& r, std::uint32_t by) {
    return {r.x - by, r.y - by, r.width + 2 * by, r.height + 2 * by};
}

void expect_packed(const std::vector<glm::uvec2>& sizes, const std::vector<atlas_rect>& rects, std::uint32_t width,
                   std::uint32_t height, std::uint32_t gutter) {
    ASSERT_EQ(rects.size(), sizes.size());
    for (std::size_t i = 0; i < rects.size(); ++i) {
        EXPECT_EQ(rects[i].width, sizes[i].x);
        EXPECT_EQ(rects[i].height, sizes[i].y);
        EXPECT_GE(rects[i].x, gutter);
        EXPECT_GE(rects[i].y, gutter);
        EXPECT_LE(rects[i].x + rects[i].width + gutter, width);
        EXPECT_LE(rects[i].y + rects[i].height + gutter, height);
        for (std::size_t j = 0; j < i; ++j) {
            ASSERT_FALSE(overlaps(rects[i], rects[j])) << i << " and " << j;
            // A gutter-wide frame around one never reaches into the other.
            if (gutter) {
                ASSERT_FALSE(overlaps(grown(rects[i], gutter), rects[j])) << i << " and " << j;
            }
        }
    }
}

TEST(atlas_packing, hundreds_of_random_rectangles_never_overlap_and_keep_their_gutter) {
    rng random(1);
    std::vector<glm::uvec2> sizes;
    for (int i = 0; i < 400; ++i) sizes.push_back({4 + random.below(40), 4 + random.below(40)});
    for (const std::uint32_t gutter : {0u, 1u, 2u, 4u}) {
        const auto rects = pack_atlas(sizes, 1024, 1024, gutter);
        ASSERT_TRUE(rects) << "gutter " << gutter;
        expect_packed(sizes, *rects, 1024, 1024, gutter);
    }
}

// Four 8 x 8 rectangles with a 1-texel gutter need 1 + 8 + 1 + 8 + 1 = 19 texels each way.
TEST(atlas_packing, a_hand_counted_tight_fit_fits_and_one_texel_less_does_not) {
    const std::vector<glm::uvec2> sizes(4, glm::uvec2(8, 8));
    const auto rects = pack_atlas(sizes, 19, 19, 1);
    ASSERT_TRUE(rects);
    expect_packed(sizes, *rects, 19, 19, 1);
    EXPECT_FALSE(pack_atlas(sizes, 18, 19, 1));
    EXPECT_FALSE(pack_atlas(sizes, 19, 18, 1));
    EXPECT_FALSE(pack_atlas(std::vector<glm::uvec2>{{20, 1}}, 19, 19, 0));
    EXPECT_TRUE(pack_atlas(std::vector<glm::uvec2>{}, 19, 19, 1));
}

// With a stable sort, equal-sized rectangles are placed in their given order: reading order.
TEST(atlas_packing, equal_sized_rectangles_are_placed_in_their_given_order) {
    const std::vector<glm::uvec2> sizes(9, glm::uvec2(10, 10));
    const auto rects = pack_atlas(sizes, 34, 34, 1);  // 3 x 3 of 11 texels plus one gutter
    ASSERT_TRUE(rects);
    for (std::uint32_t i = 0; i < 9; ++i) {
        EXPECT_EQ((*rects)[i].x, 1 + (i % 3) * 11) << i;
        EXPECT_EQ((*rects)[i].y, 1 + (i / 3) * 11) << i;
    }
}

TEST(atlas_packing, bad_sizes_are_named) {
    EXPECT_THROW(pack_atlas(std::vector<glm::uvec2>{{0, 4}}, 64, 64, 1), std::invalid_argument);
    EXPECT_THROW(pack_atlas(std::vector<glm::uvec2>{{4, 4}}, 0, 64, 1), std::invalid_argument);
}

}  // namespace
}  // namespace sylva
