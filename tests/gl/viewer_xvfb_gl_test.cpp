// The windowed viewer (GLFW) under a virtual X server: it plays a few frames, saves a
// screenshot, and the screenshot must match the headless (OSMesa) render of the same frame.
#include <gtest/gtest.h>

#include <cstdlib>
#include <unistd.h>
#include <filesystem>
#include <string>

#include "../golden/golden_support.h"
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

}  // namespace
}  // namespace sylva
