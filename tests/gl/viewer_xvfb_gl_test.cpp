// The windowed viewer (GLFW) under a virtual X server: it plays a few frames, saves a
// screenshot, and the screenshot must match the headless (OSMesa) render of the same frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <unistd.h>
#include <filesystem>
#include <string>

#include "../golden/golden_support.h"
#include "app/rung_colours.h"
#include "models/image/image.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

int run(const std::string& command) { return std::system((command + " >/dev/null 2>&1").c_str()); }

TEST(viewer, xvfb_screenshot_matches_the_headless_render_of_the_same_frame) {
    if (run("command -v xvfb-run") != 0) GTEST_SKIP() << "xvfb-run is not installed (package xvfb)";
    const fs::path dir = fs::temp_directory_path() / ("sylva_viewer_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string binary = SYLVA_BINARY;
    const std::string scenario = std::string(SYLVA_SOURCE_DIR) + "/scenarios/tiny.json";
    ASSERT_EQ(run(binary + " play " + scenario + " --headless --frames 3 --out " + (dir / "headless").string()), 0);
    // Unset DISPLAY so xvfb-run's server is the only one the viewer can reach.
    ASSERT_EQ(run("env -u WAYLAND_DISPLAY xvfb-run -a -s '-screen 0 640x480x24' " + binary + " view " +
                  scenario + " --exit-after 3 --no-overlay --screenshot " + (dir / "window.png").string()),
              0);
    const image_rgba8 headless = testing::read_png(dir / "headless/frame_0002.png");
    const image_rgba8 window = testing::read_png(dir / "window.png");
    ASSERT_FALSE(headless.texels.empty());
    ASSERT_FALSE(window.texels.empty());
    const auto d = testing::compare_images(headless, window);
    EXPECT_GT(d.psnr_db, 35.0) << "mean abs " << d.mean_absolute;
    fs::remove_all(dir);
}

// The overlay's auto-ladder slider (budget, frame-time target, error threshold or gain) draws
// with each of the four aims, and the viewer runs through them to the end.
TEST(viewer, the_overlay_draws_the_auto_ladder_slider_for_each_aim) {
    if (run("command -v xvfb-run") != 0) GTEST_SKIP() << "xvfb-run is not installed (package xvfb)";
    const std::string command = "env -u WAYLAND_DISPLAY xvfb-run -a -s '-screen 0 640x480x24' " +
                                std::string(SYLVA_BINARY) + " view " + SYLVA_SOURCE_DIR +
                                "/scenarios/tiny.json --representation ladder --exit-after 3 ";
    for (const char* aim : {"--plant-budget-ms 5", "--target-frame-ms 50", "--max-error 0.05", "--gain-per-ms 40",
                            "--gain-per-ms 40 --plant-budget-ms 5"})
        EXPECT_EQ(run(command + aim), 0) << aim;
    EXPECT_NE(run(command + "--max-error 0.05 --plant-budget-ms 5"), 0) << "two aims at once are refused";
}

// R's rung colours (app/rung_colours.h): with the ladder on tiny, the screenshot shows the key's
// colours where plants stand and nothing of them without --rungs.
TEST(viewer, rung_colours_tint_plants_by_their_rung) {
    if (run("command -v xvfb-run") != 0) GTEST_SKIP() << "xvfb-run is not installed (package xvfb)";
    const fs::path dir = fs::temp_directory_path() / ("sylva_viewer_rungs_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string command = "env -u WAYLAND_DISPLAY xvfb-run -a -s '-screen 0 640x480x24' " +
                                std::string(SYLVA_BINARY) + " view " + SYLVA_SOURCE_DIR +
                                "/scenarios/tiny.json --representation ladder --exit-after 3 --no-overlay";
    ASSERT_EQ(run(command + " --rungs --screenshot " + (dir / "rungs.png").string()), 0);
    ASSERT_EQ(run(command + " --screenshot " + (dir / "plain.png").string()), 0);
    // Pixels exactly a key colour times the brightness factor: the hue of the key, saturated.
    const auto keyed = [](const image_rgba8& image, const rung_colour& c) {
        std::size_t n = 0;
        for (std::size_t i = 0; i + 3 < image.texels.size(); i += 4) {
            const int r = image.texels[i], g = image.texels[i + 1], b = image.texels[i + 2];
            const int scale = std::max({r, g, b});
            const int key = std::max({int(c.rgb[0]), int(c.rgb[1]), int(c.rgb[2])});
            if (scale < 30) continue;
            bool match = true;
            for (int k = 0; k < 3; ++k) match = match && std::abs(image.texels[i + std::size_t(k)] * key - int(c.rgb[std::size_t(k)]) * scale) <= 3 * key;
            n += match;
        }
        return n;
    };
    const image_rgba8 rungs = testing::read_png(dir / "rungs.png");
    const image_rgba8 plain = testing::read_png(dir / "plain.png");
    std::size_t tinted = 0, untinted = 0;
    for (const rung_colour& c : k_rung_colours) {
        tinted += keyed(rungs, c);
        untinted += keyed(plain, c);
    }
    EXPECT_GT(tinted, 200u);
    EXPECT_LT(untinted * 20, tinted);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
