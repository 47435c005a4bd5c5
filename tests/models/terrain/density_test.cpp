#include "models/terrain/density.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <vector>

namespace sylva {
namespace {

TEST(density_map, at_is_bilinear_between_texel_centres_and_clamped) {
    density_map m{2, 1, {0.0f, 1.0f}};
    EXPECT_FLOAT_EQ(m.at(0.25, 0.5), 0.0f);  // centre of texel 0
    EXPECT_FLOAT_EQ(m.at(0.75, 0.5), 1.0f);
    EXPECT_FLOAT_EQ(m.at(0.5, 0.5), 0.5f);
    EXPECT_FLOAT_EQ(m.at(-3.0, 9.0), 0.0f);
    EXPECT_FLOAT_EQ(m.at(3.0, -9.0), 1.0f);
    EXPECT_FLOAT_EQ(density_map{}.at(0.3, 0.3), 1.0f);
}

TEST(density_map, loads_8_and_16_bit_greyscale_png) {
    const auto dir = std::filesystem::temp_directory_path();
    for (const OIIO::TypeDesc type : {OIIO::TypeDesc::UINT8, OIIO::TypeDesc::UINT16}) {
        SCOPED_TRACE(type.c_str());
        const auto path = dir / (std::string("sylva_density_") + type.c_str() + ".png");
        // 2 x 2: black, white / white, black.
        const unsigned max = type == OIIO::TypeDesc::UINT8 ? 255u : 65535u;
        const std::vector<std::uint16_t> v16{0, std::uint16_t(max), std::uint16_t(max), 0};
        const std::vector<std::uint8_t> v8{0, 255, 255, 0};
        auto out = OIIO::ImageOutput::create(path.string());
        ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(2, 2, 1, type)));
        ASSERT_TRUE(out->write_image(type, type == OIIO::TypeDesc::UINT8
                                               ? static_cast<const void*>(v8.data())
                                               : v16.data()));
        out->close();
        const density_map m = load_density_map(path);
        EXPECT_EQ(m.width, 2u);
        EXPECT_EQ(m.height, 2u);
        EXPECT_EQ(m.values, (std::vector<float>{0.0f, 1.0f, 1.0f, 0.0f}));
        std::filesystem::remove(path);
    }
    EXPECT_THROW(load_density_map(dir / "sylva_density_missing.png"), std::runtime_error);
}

TEST(procedural_density, coverage_is_the_dense_fraction_and_seeded) {
    for (const float coverage : {0.2f, 0.5f, 0.8f}) {
        SCOPED_TRACE(coverage);
        const density_map m = procedural_density(7, 3.0f, coverage);
        const auto dense =
            std::count_if(m.values.begin(), m.values.end(), [](float d) { return d >= 0.5f; });
        EXPECT_NEAR(double(dense) / double(m.values.size()), coverage, 0.02);
        EXPECT_TRUE(std::all_of(m.values.begin(), m.values.end(),
                                [](float d) { return d >= 0.0f && d <= 1.0f; }));
    }
    EXPECT_EQ(procedural_density(7, 3.0f, 0.5f).values, procedural_density(7, 3.0f, 0.5f).values);
    EXPECT_NE(procedural_density(7, 3.0f, 0.5f).values, procedural_density(8, 3.0f, 0.5f).values);
    const density_map none = procedural_density(7, 3.0f, 0.0f);
    const density_map all = procedural_density(7, 3.0f, 1.0f);
    EXPECT_TRUE(
        std::all_of(none.values.begin(), none.values.end(), [](float d) { return d == 0.0f; }));
    EXPECT_TRUE(
        std::all_of(all.values.begin(), all.values.end(), [](float d) { return d == 1.0f; }));
}

}  // namespace
}  // namespace sylva
