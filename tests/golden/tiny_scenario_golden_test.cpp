// Golden image of the small `tiny` scenario, rendered headless on OSMesa. The committed golden
// is tests/golden/data/tiny_frame_0003.png; SYLVA_UPDATE_GOLDEN=1 rewrites it after an intended
// change (look at the new image before committing it).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <filesystem>
#include <set>

#include "../gl/gl_test_support.h"
#include "app/scenario_player.h"
#include "golden_support.h"
#include "models/textures.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

const std::filesystem::path k_golden =
    std::filesystem::path(SYLVA_SOURCE_DIR) / "tests/golden/data/tiny_frame_0003.png";

image_rgba8 read_png(const std::filesystem::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) return {};
    const auto& spec = in->spec();
    image_rgba8 image;
    image.width = std::uint32_t(spec.width);
    image.height = std::uint32_t(spec.height);
    image.texels.resize(std::size_t(spec.width) * spec.height * 4);
    in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, image.texels.data());
    return image;
}

image_rgba8 render_tiny_frame(std::uint64_t frame, render::gl_context& context) {
    scenario s = load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "scenarios/tiny.json");
    scenario_player player(s, 2, &context);
    for (std::uint64_t f = 0; f <= frame; ++f) player.step();
    return player.capture();
}

std::unique_ptr<render::gl_context> tiny_context() {
    const scenario s = load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "scenarios/tiny.json");
    render::context_options options;
    options.width = int(s.width);
    options.height = int(s.height);
    options.headless = true;
    return render::create_context(options);
}

TEST(golden, tiny_scenario_frame_3_matches_the_committed_image) {
    SYLVA_REQUIRE_GL();
    auto context = tiny_context();
    const image_rgba8 image = render_tiny_frame(3, *context);
    if (const char* update = std::getenv("SYLVA_UPDATE_GOLDEN"); update && std::string(update) == "1") {
        std::filesystem::create_directories(k_golden.parent_path());
        write_image(image, k_golden);
        GTEST_SKIP() << "golden rewritten: " << k_golden;
    }
    const image_rgba8 golden = read_png(k_golden);
    ASSERT_FALSE(golden.texels.empty()) << "missing golden " << k_golden;
    const auto d = testing::compare_images(image, golden);
    // Same renderer, same inputs: expected identical; allow rasteriser last-bit noise.
    EXPECT_GT(d.psnr_db, 40.0);
    EXPECT_LT(d.fraction_over_16, 0.002);
}

TEST(golden, the_frame_is_a_lit_landscape_not_a_blank_image) {
    SYLVA_REQUIRE_GL();
    auto context = tiny_context();
    const image_rgba8 image = render_tiny_frame(0, *context);
    // Sky at the top (bluish, bright), darker vegetation and ground lower down, many colours.
    double top_blue = 0.0, bottom_luma = 0.0, top_luma = 0.0;
    const std::uint32_t w = image.width, h = image.height;
    for (std::uint32_t x = 0; x < w; ++x) {
        const auto* top = image.at(x, 1);
        const auto* bottom = image.at(x, h - 2);
        top_blue += double(top[2]) - double(top[0]);
        top_luma += 0.3 * top[0] + 0.59 * top[1] + 0.11 * top[2];
        bottom_luma += 0.3 * bottom[0] + 0.59 * bottom[1] + 0.11 * bottom[2];
    }
    EXPECT_GT(top_blue / w, 10.0);
    EXPECT_GT(top_luma, bottom_luma);
    std::set<std::uint32_t> colours;
    for (std::size_t p = 0; p < image.texels.size(); p += 4)
        colours.insert(std::uint32_t(image.texels[p]) << 16 | std::uint32_t(image.texels[p + 1]) << 8 |
                       image.texels[p + 2]);
    EXPECT_GT(colours.size(), 500u);
}

}  // namespace
}  // namespace sylva
