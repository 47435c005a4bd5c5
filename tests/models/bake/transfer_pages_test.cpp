#include "models/bake/transfer_pages.h"

#include <gtest/gtest.h>

namespace sylva {
namespace {

TEST(transfer_pages, encoding_by_hand) {
    // (T / 1.25) * 0.5 + 0.5 in 8 bits: 0 -> 127.5 -> 128; 1.25 -> 255; -1.25 -> 0; 0.5 -> 178.5.
    EXPECT_EQ(encode_transfer(0.0f), 128);
    EXPECT_EQ(encode_transfer(1.25f), 255);
    EXPECT_EQ(encode_transfer(-1.25f), 0);
    EXPECT_EQ(encode_transfer(0.5f), 179);
    EXPECT_EQ(encode_transfer(9.0f), 255);  // clamped
    // Half a step (2.5 / 255 per byte) at most, plus float rounding.
    EXPECT_NEAR(decode_transfer(179), 0.5f, 1.26f / 255.0f);
    EXPECT_NEAR(decode_transfer(encode_transfer(-0.7f)), -0.7f, 1.26f / 255.0f);
}

TEST(transfer_pages, blit_writes_eighteen_coefficients_across_five_pages) {
    billboard_image image;
    image.albedo = {2, 1, std::vector<std::uint8_t>(8, 0)};
    image.transfer.assign(2 * k_billboard_transfer_floats, 0.0f);
    for (std::size_t i = 0; i < k_billboard_transfer_floats; ++i)
        image.transfer[k_billboard_transfer_floats + i] = 0.05f * float(i);
    std::vector<image_rgba8> pages = blank_transfer_pages(4, 2);
    blit_transfer(pages, image, 2, 1);
    // Texel (3, 1) holds the second image texel: coefficient 9 (the other side's first) is page
    // 2's green channel, coefficient 17 page 4's green; the padding stays zero.
    EXPECT_EQ(pages[2].at(3, 1)[1], encode_transfer(0.45f));
    EXPECT_EQ(pages[4].at(3, 1)[1], encode_transfer(0.85f));
    EXPECT_EQ(pages[4].at(3, 1)[2], 128);
    EXPECT_EQ(pages[0].at(2, 1)[0], 128);  // the first image texel: all zero
    EXPECT_EQ(pages[0].at(0, 0)[0], 128);  // outside the image: untouched blank
    billboard_image without_transfer = image;
    without_transfer.transfer.clear();
    EXPECT_THROW(blit_transfer(pages, without_transfer, 0, 0), std::invalid_argument);
}

}  // namespace
}  // namespace sylva
