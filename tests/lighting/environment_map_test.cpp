// Environment maps written by the tests themselves (OpenImageIO writes .hdr and .exr), read back
// and projected: hand values for a constant map, a bright upper hemisphere and an eastern lune,
// and every load error naming the file and the problem.
#include "lighting/environment_map.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>

namespace sylva {
namespace {

constexpr int k_height = 32;
constexpr int k_width = 2 * k_height;

std::filesystem::path temp_path(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / "sylva_environment_map_test";
    std::filesystem::create_directories(dir);
    return dir / name;
}

// Writes width x height texels of `channels` channels, texel (i, j) from `texel`.
std::filesystem::path write_map(const std::string& name, int width, int height, int channels,
                                const std::function<glm::vec3(int, int)>& texel,
                                OIIO::TypeDesc format = OIIO::TypeDesc::FLOAT) {
    const std::filesystem::path path = temp_path(name);
    std::vector<float> pixels;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const glm::vec3 v = texel(i, j);
            for (int c = 0; c < channels; ++c) pixels.push_back(v[c % 3]);
        }
    auto out = OIIO::ImageOutput::create(path.string());
    EXPECT_TRUE(out) << OIIO::geterror();
    EXPECT_TRUE(out->open(path.string(), OIIO::ImageSpec(width, height, channels, format)));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
    out->close();
    return path;
}

std::string load_error(const std::filesystem::path& path) {
    try {
        load_environment_map(path);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(environment_map, constant_map_projects_to_band_zero_only) {
    // c0 = integral of L Y0 = L 4 pi / (2 sqrt(pi)) = L sqrt(4 pi) = 3.544908 L, all others 0.
    // The texels are integrated exactly, so this holds to float rounding on 32 rows. 2.5, 1.25
    // and 0.5 are exact in RGBE (.hdr stores 8-bit mantissas).
    const glm::vec3 l(2.5f, 1.25f, 0.5f);
    const auto path = write_map("constant.hdr", k_width, k_height, 3, [&](int, int) { return l; });
    const environment_map map = load_environment_map(path);
    ASSERT_EQ(map.width, k_width);
    EXPECT_EQ(map.sanitised_texels, 0u);
    const sh9_rgb c = project_environment_map(map);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(c.c[0][ch], 3.544908f * l[ch], 1e-5f * l[ch]);
    for (std::size_t i = 1; i < 9; ++i) EXPECT_NEAR(c.c[i].x, 0.0f, 1e-5f * l.x) << i;
}

TEST(environment_map, bright_upper_hemisphere_gives_the_hand_band_one_value) {
    // L = 1 above the horizon (rows 0..15 of 32: the horizon is a row boundary), 0 below.
    //   c0 = Y0 2 pi = sqrt(pi) = 1.772454;  c1 ("y") = 0.488603 * integral of y over the upper
    //   hemisphere = sqrt(3 / (4 pi)) pi = sqrt(3 pi) / 2 = 1.534990; all others 0 by symmetry.
    const auto path = write_map("upper.exr", k_width, k_height, 3, [](int, int j) {
        return glm::vec3(j < k_height / 2 ? 1.0f : 0.0f);
    });
    const sh9_rgb c = project_environment_map(load_environment_map(path));
    EXPECT_NEAR(c.c[0].x, 1.772454f, 1e-5f);
    EXPECT_NEAR(c.c[1].x, 1.534990f, 1e-5f);
    for (std::size_t i : {2u, 3u, 4u, 5u, 6u, 7u, 8u}) EXPECT_NEAR(c.c[i].x, 0.0f, 1e-5f) << i;
}

TEST(environment_map, eastern_lune_lands_on_plus_x) {
    // Orientation check: columns 40..55 of 64 are u = 0.625 .. 0.875, azimuth 45 .. 135 degrees
    // (north-east to south-east), i.e. centred on east (+x). Integral of x over the lune =
    // integral of sin^2(theta) dtheta * integral of sin(phi) dphi = (pi / 2) * sqrt(2) = 2.221441,
    // so c3 ("x") = 0.4886025 * 2.2214415 = 1.0854019, and c2 ("z") = 0 (symmetric about east).
    const auto path = write_map("east.exr", k_width, k_height, 3, [](int i, int) {
        return glm::vec3(i >= 40 && i < 56 ? 1.0f : 0.0f);
    });
    const sh9_rgb c = project_environment_map(load_environment_map(path));
    EXPECT_NEAR(c.c[3].x, 1.0854019f, 1e-5f);
    EXPECT_NEAR(c.c[2].x, 0.0f, 1e-5f);
    EXPECT_NEAR(c.c[1].x, 0.0f, 1e-5f);
    // And the direction of a texel says the same: column 47 (u = 0.7422) is close to east.
    const glm::vec3 d = environment_map_direction(47, k_height / 2, k_width, k_height);
    EXPECT_GT(d.x, 0.99f);
}

TEST(environment_map, nan_infinite_and_negative_texels_are_zeroed_and_counted) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const auto bad = [&](int i, int j) {
        if (i == 3 && j == 4) return glm::vec3(nan, 1.0f, 1.0f);
        if (i == 10 && j == 20) return glm::vec3(1.0f, inf, 1.0f);
        if (i == 60 && j == 2) return glm::vec3(1.0f, 1.0f, -2.0f);
        return glm::vec3(1.0f);
    };
    const environment_map map =
        load_environment_map(write_map("bad.exr", k_width, k_height, 3, bad));
    EXPECT_EQ(map.sanitised_texels, 3u);
    const auto zeroed = [&](int i, int j) {
        const glm::vec3 v = bad(i, j);
        return std::isfinite(v.x + v.y + v.z) && v.z >= 0.0f ? v : glm::vec3(0.0f);
    };
    const sh9_rgb got = project_environment_map(map);
    const sh9_rgb expected = project_environment_map(
        load_environment_map(write_map("zeroed.exr", k_width, k_height, 3, zeroed)));
    for (std::size_t i = 0; i < 9; ++i) EXPECT_EQ(got.c[i], expected.c[i]) << i;
}

TEST(environment_map, load_errors_name_the_file_and_the_problem) {
    const std::string missing = load_error(temp_path("does_not_exist.hdr"));
    EXPECT_NE(missing.find("does_not_exist.hdr: no such file"), std::string::npos) << missing;

    const auto garbage = temp_path("garbage.hdr");
    std::ofstream(garbage) << "not an image";
    const std::string unreadable = load_error(garbage);
    EXPECT_NE(unreadable.find("garbage.hdr: cannot read it"), std::string::npos) << unreadable;

    const auto one = [](int, int) { return glm::vec3(1.0f); };
    const std::string square = load_error(write_map("square.exr", 32, 32, 3, one));
    EXPECT_NE(square.find("square.exr: is 32x32 pixels"), std::string::npos) << square;

    const std::string grey = load_error(write_map("grey.exr", 64, 32, 1, one));
    EXPECT_NE(grey.find("grey.exr: has 1 channel(s); expected RGB"), std::string::npos) << grey;

    const std::string ldr = load_error(write_map("ldr.png", 64, 32, 3, one, OIIO::TypeDesc::UINT8));
    EXPECT_NE(ldr.find("ldr.png: holds uint8 data; expected HDR"), std::string::npos) << ldr;
}

TEST(environment_map, downsampling_keeps_a_constant_and_the_mean) {
    const auto path = write_map("rows.exr", k_width, k_height, 3, [](int i, int j) {
        return glm::vec3(float(j), float(i % 2), 1.0f);
    });
    const environment_map map = load_environment_map(path);
    const environment_map small = downsample_environment_map(map, 16, 8);
    ASSERT_EQ(small.rgb.size(), 16u * 8u * 3u);
    for (int j = 0; j < 8; ++j) {
        const float* t = &small.rgb[std::size_t(j) * 16 * 3];
        EXPECT_FLOAT_EQ(t[2], 1.0f);  // the constant channel
        EXPECT_FLOAT_EQ(t[1], 0.5f);  // alternating columns average to 1/2
        // Rows 4j .. 4j+3 averaged with solid-angle weights: between the first and the last.
        EXPECT_GT(t[0], float(4 * j));
        EXPECT_LT(t[0], float(4 * j + 3));
    }
    // A map smaller than the output is sampled, not left black.
    const environment_map large = downsample_environment_map(small, 64, 32);
    for (float v : large.rgb) EXPECT_TRUE(std::isfinite(v));
    EXPECT_FLOAT_EQ(large.rgb[2], 1.0f);
}

}  // namespace
}  // namespace sylva
