#include "models/generate/textures.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace sylva {
namespace {

double alpha_fraction(const image_rgba8& im, std::uint8_t value) {
    std::size_t n = 0;
    for (std::size_t i = 3; i < im.texels.size(); i += 4) n += im.texels[i] == value;
    return double(n) / double(im.width * im.height);
}

int channel_sum_difference(const std::uint8_t* a, const std::uint8_t* b) {
    return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

class leaf_texture_test : public testing::TestWithParam<std::string> {};

TEST_P(leaf_texture_test, has_transparent_background_and_opaque_leaves) {
    const image_rgba8 im = generate_leaf_texture(GetParam(), 128);
    ASSERT_EQ(im.width, 128u);
    ASSERT_EQ(im.texels.size(), 128u * 128u * 4u);
    const double transparent = alpha_fraction(im, 0);
    const double opaque = alpha_fraction(im, 255);
    EXPECT_GT(transparent, 0.2);
    EXPECT_LT(transparent, 0.8);
    EXPECT_GT(opaque, 0.15);
    EXPECT_GT(transparent + opaque, 0.8);  // only the anti-aliased rims are in between
    for (std::uint32_t i = 0; i < 128; ++i) {  // clamped borders stay clear
        EXPECT_EQ(im.at(i, 0)[3], 0);
        EXPECT_EQ(im.at(0, i)[3], 0);
        EXPECT_EQ(im.at(127, i)[3], 0);
    }
}

TEST_P(leaf_texture_test, opaque_texels_are_green) {
    const image_rgba8 im = generate_leaf_texture(GetParam(), 64);
    std::size_t green = 0;
    std::size_t opaque = 0;
    for (std::size_t i = 0; i < im.texels.size(); i += 4) {
        if (im.texels[i + 3] != 255) continue;
        ++opaque;
        green += im.texels[i + 1] > im.texels[i] && im.texels[i + 1] > im.texels[i + 2];
    }
    EXPECT_GT(double(green) / double(opaque), 0.8);
}

TEST_P(leaf_texture_test, bark_is_opaque_and_not_flat) {
    const image_rgba8 im = generate_bark_texture(GetParam(), 128);
    EXPECT_EQ(alpha_fraction(im, 255), 1.0);
    int lo = 255;
    int hi = 0;
    for (std::size_t i = 0; i < im.texels.size(); i += 4) {
        lo = std::min<int>(lo, im.texels[i]);
        hi = std::max<int>(hi, im.texels[i]);
    }
    EXPECT_GT(hi - lo, 20);
}

TEST_P(leaf_texture_test, deterministic) {
    EXPECT_EQ(generate_leaf_texture(GetParam(), 32).texels, generate_leaf_texture(GetParam(), 32).texels);
}

INSTANTIATE_TEST_SUITE_P(generators, leaf_texture_test, testing::Values("broadleaf", "conifer"));

// The seam (across the wrap) is compared with the mean difference between horizontally or
// vertically adjacent interior texels: in a tiling texture the wrap is just another neighbour.
double mean_neighbour_difference(const image_rgba8& im, bool horizontal) {
    double sum = 0.0;
    for (std::uint32_t y = 0; y + 1 < im.height; ++y)
        for (std::uint32_t x = 0; x + 1 < im.width; ++x)
            sum += channel_sum_difference(im.at(x, y), horizontal ? im.at(x + 1, y) : im.at(x, y + 1));
    return sum / double((im.width - 1) * (im.height - 1));
}

void expect_tiles(const image_rgba8& im) {
    const std::uint32_t n = im.width;
    double seam_x = 0.0;
    double seam_y = 0.0;
    double far = 0.0;
    for (std::uint32_t i = 0; i < n; ++i) {
        seam_x += channel_sum_difference(im.at(0, i), im.at(n - 1, i));
        seam_y += channel_sum_difference(im.at(i, 0), im.at(i, n - 1));
        for (std::uint32_t k = n / 4; k < 3 * n / 4; ++k) far += channel_sum_difference(im.at(0, i), im.at(k, i));
    }
    seam_x /= n;
    seam_y /= n;
    far /= double(n) * (n / 2);
    EXPECT_LT(seam_x, 1.5 * mean_neighbour_difference(im, true));
    EXPECT_LT(seam_y, 1.5 * mean_neighbour_difference(im, false));
    // Distant columns do differ, so the comparison above has teeth.
    EXPECT_GT(far, 2.0 * seam_x);
}

TEST(ground_texture, tiles_seamlessly_and_is_opaque) {
    const image_rgba8 im = generate_ground_texture(128);
    EXPECT_EQ(alpha_fraction(im, 255), 1.0);
    expect_tiles(im);
}

TEST(bark_texture, tiles_seamlessly) {
    expect_tiles(generate_bark_texture("broadleaf", 128));
    expect_tiles(generate_bark_texture("conifer", 128));
}

TEST(textures, unknown_generator_throws) {
    EXPECT_THROW(generate_leaf_texture("palm", 16), std::invalid_argument);
    EXPECT_THROW(generate_bark_texture("palm", 16), std::invalid_argument);
}

TEST(write_image, round_trip_to_png_and_error_names_the_file) {
    const auto path = std::filesystem::temp_directory_path() / "sylva_models_test_leaf.png";
    write_image(generate_leaf_texture("broadleaf", 32), path);
    EXPECT_GT(std::filesystem::file_size(path), 0u);
    std::filesystem::remove(path);
    const std::filesystem::path bad = "/nonexistent_dir_sylva/x.png";
    try {
        write_image(generate_ground_texture(8), bad);
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos);
    }
}

}  // namespace
}  // namespace sylva
