// measure/crown_texture: the crown mask's interior and the Laplacian's variance, hand-computed.
#include "measure/crown_texture.h"

#include <gtest/gtest.h>

namespace sylva {
namespace {

image_rgba8 grey(std::uint32_t w, std::uint32_t h, std::uint8_t value) {
    image_rgba8 image;
    image.width = w;
    image.height = h;
    image.texels.assign(std::size_t(w) * h * 4, value);
    return image;
}

void set_grey(image_rgba8& image, std::uint32_t x, std::uint32_t y, std::uint8_t value) {
    std::uint8_t* p = image.at(x, y);
    p[0] = p[1] = p[2] = value;
}

TEST(crown_texture, the_interior_leaves_out_pixels_near_the_edge_or_a_hole) {
    std::vector<std::uint8_t> mask(25, 1);
    mask[0] = 0;  // (0, 0) is sky
    const std::vector<std::uint8_t> inside = mask_interior(mask, 5, 5, 1);
    // Radius 1: only the central 3x3 can have a whole neighbourhood, and (1, 1) touches the hole.
    for (std::uint32_t y = 0; y < 5; ++y)
        for (std::uint32_t x = 0; x < 5; ++x) {
            const bool expected = x >= 1 && x <= 3 && y >= 1 && y <= 3 && !(x == 1 && y == 1);
            EXPECT_EQ(inside[y * 5 + x] != 0, expected) << x << "," << y;
        }
    EXPECT_THROW(mask_interior(mask, 4, 5, 1), std::invalid_argument);
}

TEST(crown_texture, one_bright_pixel_gives_the_hand_computed_laplacian_variance) {
    // Grey 10 everywhere, 20 at the centre of a 5x5 image; the interior is the central 3x3.
    image_rgba8 image = grey(5, 5, 10);
    set_grey(image, 2, 2, 20);
    const std::vector<std::uint8_t> inside = mask_interior(std::vector<std::uint8_t>(25, 1), 5, 5, 1);
    const crown_texture t = crown_texture_of(image, inside);
    // Laplacians: centre 4·20 − 4·10 = 40; its four neighbours 4·10 − (3·10 + 20) = −10; the four
    // corners 0. Mean 0, variance (40² + 4·10²) / 9 = 222.2; mean luma (20 + 8·10) / 9 = 11.11.
    EXPECT_EQ(t.pixels, 9u);
    EXPECT_NEAR(t.laplacian_variance, 2000.0 / 9.0, 1e-9);
    EXPECT_NEAR(t.mean_luma, 100.0 / 9.0, 1e-9);
    // A flat crown has none.
    EXPECT_NEAR(crown_texture_of(grey(5, 5, 10), inside).laplacian_variance, 0.0, 1e-12);
    // Pooled with a flat crown of 9 pixels at grey 10: 18 pixels, Laplacians 40, 4 × −10 and 13 × 0,
    // variance 2000 / 18; mean luma (100 + 90) / 18.
    const crown_texture both = pooled(t, crown_texture_of(grey(5, 5, 10), inside));
    EXPECT_EQ(both.pixels, 18u);
    EXPECT_NEAR(both.laplacian_variance, 2000.0 / 18.0, 1e-9);
    EXPECT_NEAR(both.mean_luma, 190.0 / 18.0, 1e-9);
    // Nothing marked: zeros, not a division by zero.
    EXPECT_EQ(crown_texture_of(image, std::vector<std::uint8_t>(25, 0)).pixels, 0u);
}

}  // namespace
}  // namespace sylva
