#pragma once
// Golden-image helpers shared by the golden tests (and the viewer's screenshot test): reading a
// PNG, comparing two images with a tolerance (the rasteriser may differ in the last bit between
// Mesa builds), rendering one frame of a scenario headless, and checking a frame against its
// committed golden in tests/golden/data/, which SYLVA_UPDATE_GOLDEN=1 rewrites instead (look at
// the new image before committing it).
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/scenario_player.h"
#include "models/image/image.h"
#include "models/generate/textures.h"
#include "scenarios/scenario_loader.h"
#include "systems/render/gl_context.h"

namespace sylva::testing {

struct image_difference {
    double mean_absolute = 0.0;  // per channel, 0..255
    double max_absolute = 0.0;
    double psnr_db = 0.0;           // RGB, peak 255; infinity when identical
    double fraction_over_16 = 0.0;  // fraction of pixels with any channel off by more than 16
};

inline image_difference compare_images(const image_rgba8& a, const image_rgba8& b) {
    image_difference d;
    if (a.width != b.width || a.height != b.height) {
        d.mean_absolute = d.max_absolute = 255.0;
        d.fraction_over_16 = 1.0;
        return d;
    }
    double sum = 0.0, squared = 0.0;
    std::size_t over = 0;
    const std::size_t pixels = std::size_t(a.width) * a.height;
    for (std::size_t p = 0; p < pixels; ++p) {
        bool pixel_over = false;
        for (int c = 0; c < 3; ++c) {
            const double diff = std::abs(double(a.texels[p * 4 + c]) - double(b.texels[p * 4 + c]));
            sum += diff;
            squared += diff * diff;
            d.max_absolute = std::max(d.max_absolute, diff);
            pixel_over = pixel_over || diff > 16.0;
        }
        over += pixel_over ? 1 : 0;
    }
    d.mean_absolute = sum / double(pixels * 3);
    const double mse = squared / double(pixels * 3);
    d.psnr_db = mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : INFINITY;
    d.fraction_over_16 = double(over) / double(pixels);
    return d;
}

// An RGBA8 image from a PNG (any channel count, converted); empty when it cannot be read.
inline image_rgba8 read_png(const std::filesystem::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) return {};
    image_rgba8 image;
    image.width = std::uint32_t(in->spec().width);
    image.height = std::uint32_t(in->spec().height);
    image.texels.resize(std::size_t(image.width) * image.height * 4);
    if (!in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, image.texels.data())) return {};
    return image;
}

inline std::filesystem::path golden_data(const std::string& file) {
    return std::filesystem::path(SYLVA_SOURCE_DIR) / "tests/golden/data" / file;
}

// A headless context of the scenario's size (the renderer draws at the context's size).
inline std::unique_ptr<render::gl_context> headless_context(const scenario& s) {
    render::context_options options;
    options.width = int(s.width);
    options.height = int(s.height);
    options.headless = true;
    return render::create_context(options);
}

struct rendered_frame {
    image_rgba8 image;
    frame_record record;  // what the frame drew: instances by representation, points, lines
    std::vector<lighting_variant> species_lighting;  // how the player lit each species
    std::size_t plants = 0;                          // spawned
};

// Plays `s` from its first frame through `frame` (the frames before may set up state the last
// one reads) in a context of its own, two threads, no bake cache (the assets are built from
// the scenario every time: a golden must not depend on what a cache holds).
inline rendered_frame render_frame(const scenario& s, std::uint64_t frame,
                                   player_options options = {}) {
    auto context = headless_context(s);
    scenario_player player(s, 2, context.get(), nullptr, std::move(options));
    rendered_frame r;
    for (std::uint64_t f = 0; f <= frame; ++f) r.record = player.step();
    r.image = player.capture();
    for (const species_entry& species : player.assets().library.species)
        r.species_lighting.push_back(species.lighting);
    r.plants = player.info().plants;
    return r;
}

// How far a frame may be from its golden. The same Mesa renders bit-identical frames (every
// golden measures infinite PSNR against itself); the slack is for another Mesa build's
// last-bit rasteriser and rounding differences. Measured as their stand-in: moving the camera
// of every golden scene by 0.1 mm (a few thousandths of a pixel) left PSNR >= 44.9 dB and at
// most 0.04 % of the pixels off by more than 16; every shader mutation tried
// (tests/golden/representation_golden_test.cpp) moved at least 0.36 % of them.
struct golden_tolerance {
    double min_psnr_db = 40.0;
    double max_fraction_over_16 = 0.002;
};

inline bool updating_goldens() {
    const char* update = std::getenv("SYLVA_UPDATE_GOLDEN");
    return update && std::string(update) == "1";
}

// Checks `image` against tests/golden/data/<file> and prints what it measured (the margins
// the tolerances are chosen from); with SYLVA_UPDATE_GOLDEN=1 rewrites the golden and skips.
inline void expect_matches_golden(const image_rgba8& image, const std::string& file,
                                  golden_tolerance tolerance = {}) {
    const std::filesystem::path path = golden_data(file);
    if (updating_goldens()) {
        write_image(image, path);
        GTEST_SKIP() << "golden rewritten: " << path;
    }
    const image_rgba8 golden = read_png(path);
    ASSERT_FALSE(golden.texels.empty())
        << "missing golden " << path << " (SYLVA_UPDATE_GOLDEN=1 writes it)";
    const image_difference d = compare_images(image, golden);
    std::printf(
        "golden %s: PSNR %.2f dB (at least %.1f), pixels off by > 16: %.4f (at most %.4f)\n",
        file.c_str(), d.psnr_db, tolerance.min_psnr_db, d.fraction_over_16,
        tolerance.max_fraction_over_16);
    EXPECT_GT(d.psnr_db, tolerance.min_psnr_db) << file;
    EXPECT_LT(d.fraction_over_16, tolerance.max_fraction_over_16) << file;
}

}  // namespace sylva::testing
