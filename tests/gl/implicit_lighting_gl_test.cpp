// Luft 2007's implicit-surface illumination (models/bake/implicit_illumination.h) through the
// renderer: the tree of scenarios/single_tree.json lit "implicit" shows its crown's shape instead
// of a noisy leaf cloud (Luft 2007 Figure 1). Measured as the paper argues it: the colour change
// between neighbouring crown pixels falls, and the crown darkens (the density ambient), both as
// meshes, as points and lines, as a billboard cloud and as a crossed billboard: every rung.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/scenario_player.h"
#include "gl_test_support.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

struct crown_look {
    double mean_luma = 0.0;       // over the plant's pixels, 0 .. 255
    double neighbour_change = 0.0;  // mean |Δ luma| between horizontally adjacent plant pixels
    double luma_entropy = 0.0;    // bits, of the plant's pixels' luma rounded to integers
    double dark_share = 0.0;      // of the plant's pixels, those darker than 24 of 255 (ink)
    // The same inside the crown only: plant pixels whose 5x5 neighbourhood is all plant, so
    // the silhouette's lines (which both lightings draw) do not count (issue 22: "edge pixels
    // inside crowns ... at equal silhouette edges").
    double interior_dark_share = 0.0;
};

crown_look look_of(const std::string& lighting, const std::string& representation,
                   const std::string& style = "photo", float sample_distance_px = 1.0f, float ka_min = -1.0f) {
    scenario s = load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "scenarios/single_tree.json");
    s.width = 320;
    s.height = 180;
    s.lod.plant_budget_ms = 0.0;  // by projected size (the file ships a budget)
    // A one-rung ladder draws every plant on that rung.
    if (representation == "billboard_cloud" || representation == "crossed_billboard") {
        s.lod.representation = "ladder";
        s.lod.ladder = {{representation, 0.0f, 0.15f}};
    } else {
        s.lod.representation = representation;
    }
    s.lod.lighting = lighting;
    s.lod.sample_distance_px = sample_distance_px;
    s.render.style = style;
    // A tenth of the leaves as generators keeps the bake short (§3.1: "very similar results").
    for (species_settings& species : s.species) {
        species.implicit.generator_fraction = 0.1f;
        if (ka_min >= 0.0f) species.implicit.ka_min = ka_min;
    }
    player_options options;
    options.id_buffer = true;
    scenario_player player(s, 2, testing::shared_gl_context(), nullptr, options);
    player.step();
    const image_rgba8 image = player.capture();
    const std::vector<std::uint32_t> ids = player.capture_plant_ids();
    const auto luma = [&](std::size_t i) {
        const std::uint8_t* p = &image.texels[4 * i];
        return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    };
    crown_look out;
    std::size_t pixels = 0, pairs = 0;
    std::array<std::size_t, 256> histogram{};
    for (std::size_t y = 0; y < image.height; ++y)
        for (std::size_t x = 0; x < image.width; ++x) {
            const std::size_t i = y * image.width + x;
            if (ids[i] == 0) continue;
            out.mean_luma += luma(i);
            ++histogram[std::size_t(std::lround(luma(i)))];
            out.dark_share += luma(i) < 24.0 ? 1.0 : 0.0;
            ++pixels;
            if (x + 1 < image.width && ids[i + 1] != 0) {
                out.neighbour_change += std::abs(luma(i + 1) - luma(i));
                ++pairs;
            }
        }
    std::size_t interior = 0;
    for (std::size_t y = 2; y + 2 < image.height; ++y)
        for (std::size_t x = 2; x + 2 < image.width; ++x) {
            bool inside = true;
            for (std::size_t v = y - 2; v <= y + 2 && inside; ++v)
                for (std::size_t u = x - 2; u <= x + 2 && inside; ++u) inside = ids[v * image.width + u] != 0;
            if (!inside) continue;
            ++interior;
            out.interior_dark_share += luma(y * image.width + x) < 24.0 ? 1.0 : 0.0;
        }
    out.interior_dark_share /= double(std::max<std::size_t>(interior, 1));
    EXPECT_GT(pixels, 2000u) << "the tree should fill part of the frame";
    out.mean_luma /= double(std::max<std::size_t>(pixels, 1));
    out.dark_share /= double(std::max<std::size_t>(pixels, 1));
    out.neighbour_change /= double(std::max<std::size_t>(pairs, 1));
    for (const std::size_t n : histogram)
        if (n > 0) {
            const double p = double(n) / double(pixels);
            out.luma_entropy -= p * std::log2(p);
        }
    return out;
}

TEST(implicit_lighting_gl, the_crown_is_smoother_and_darker_on_every_rung) {
    SYLVA_REQUIRE_GL();
    for (const char* representation : {"mesh_levels", "points_lines", "billboard_cloud", "crossed_billboard"}) {
        SCOPED_TRACE(representation);
        const crown_look normal = look_of("normal_mapped", representation);
        // k_a,min = 0 (Eq. 4 allows it): the default's darkening is mild (mean crown luma within
        // a few percent: docs/results/implicit_lighting.md), too close to what the realigned
        // normals alone do to tell a broken decode of k_a apart.
        const crown_look implicit = look_of("implicit", representation, "photo", 1.0f, 0.0f);
        std::printf("%s: neighbour change %.2f -> %.2f, mean luma %.1f -> %.1f\n", representation,
                    normal.neighbour_change, implicit.neighbour_change, normal.mean_luma, implicit.mean_luma);
        // Realigned normals (§3.3) light the crown by its shape: less noise between neighbours
        // (measured 0.39x as meshes, 0.41x as points, 0.57x as a cloud, 0.37x as a crossed
        // billboard).
        EXPECT_LT(implicit.neighbour_change, 0.65 * normal.neighbour_change);
        // The density ambient (§3.2) darkens it (measured by 5.2, 4.5, 5.2 and 9.9 of 255; with
        // the shaders' decode of k_a broken on purpose the meshes, points and cloud brighten by
        // 4.5, 5.3 and 4.4 instead).
        EXPECT_LT(implicit.mean_luma, normal.mean_luma - 4.0);
    }
}

// Luft 2007 §4: toon shading (render.style "toon") quantises the light into bands, with the
// original normals and with the realigned ones: the crown's luma spreads over fewer values.
TEST(implicit_lighting_gl, toon_style_puts_the_crown_in_bands) {
    SYLVA_REQUIRE_GL();
    for (const char* lighting : {"normal_mapped", "implicit"}) {
        SCOPED_TRACE(lighting);
        const crown_look photo = look_of(lighting, "mesh_levels");
        const crown_look toon = look_of(lighting, "mesh_levels", "toon");
        std::printf("%s: luma entropy %.2f -> %.2f bits, neighbour change %.2f -> %.2f\n", lighting,
                    photo.luma_entropy, toon.luma_entropy, photo.neighbour_change, toon.neighbour_change);
        EXPECT_LT(toon.luma_entropy, photo.luma_entropy - 0.5);
    }
}

// Luft 2007 Figure 7: lines where the normal or depth buffer jumps (render.style "lines") clutter
// a crown lit by its leaves' own normals and leave little more than its outline when the normals
// are realigned to the implicit surface.
TEST(implicit_lighting_gl, line_style_draws_the_crown_not_every_leaf) {
    SYLVA_REQUIRE_GL();
    double inked[2] = {0.0, 0.0}, inside[2] = {0.0, 0.0};
    int i = 0;
    for (const char* lighting : {"normal_mapped", "implicit"}) {
        const crown_look photo = look_of(lighting, "mesh_levels");
        const crown_look lines = look_of(lighting, "mesh_levels", "lines");
        inked[i] = lines.dark_share - photo.dark_share;
        inside[i++] = lines.interior_dark_share - photo.interior_dark_share;
        std::printf("%s: crown pixels inked by the lines %.3f, inside the crown %.3f\n", lighting,
                    lines.dark_share - photo.dark_share, lines.interior_dark_share - photo.interior_dark_share);
    }
    EXPECT_GT(inked[1], 0.01) << "the realigned crown keeps its outline";
    EXPECT_GT(inked[0], 2.0 * inked[1]) << "the leaves' own normals should clutter the crown with lines";
    std::printf("inside the crown: %.1fx fewer inked pixels with realigned normals\n", inside[0] / std::max(inside[1], 1e-9));
    EXPECT_GT(inside[0], 5.0 * inside[1]) << "issue 22: at least 5x fewer edge pixels inside the crown";
}

// The same for soft splats (the default), which the blend pass draws without a normal: the
// visibility pass writes them, straight into the frame at d' = 1.5 (splats under
// k_splat_layer_min_side_px) and through the half-size splat layer's composite at d' = 2. Were
// the normal buffer left to what lies behind the crown, neither lighting would ink it.
TEST(implicit_lighting_gl, line_style_sees_soft_splats_drawn_directly_and_through_the_layer) {
    SYLVA_REQUIRE_GL();
    for (const float d : {1.5f, 2.0f}) {
        double inked[2] = {0.0, 0.0};
        int i = 0;
        for (const char* lighting : {"normal_mapped", "implicit"}) {
            const crown_look photo = look_of(lighting, "points_lines", "photo", d);
            const crown_look lines = look_of(lighting, "points_lines", "lines", d);
            inked[i++] = lines.dark_share - photo.dark_share;
            std::printf("d' = %.1f, %s: crown pixels inked by the lines %.3f\n", d, lighting,
                        lines.dark_share - photo.dark_share);
        }
        EXPECT_GT(inked[1], 0.01) << "d' = " << d << ": the realigned crown keeps its outline";
        EXPECT_GT(inked[0], 2.0 * inked[1])
            << "d' = " << d << ": the samples' own normals should clutter the crown with lines";
    }
}

// Lighting "sh_implicit": SH transfer (Behrendt 2005 §4) baked from the realigned normals, the sky's
// light times k_a. The transfer's self-shadowing already darkens the crown's inside, so the gain
// is smaller than over plain normals; what it must still do is shade the crown more smoothly and
// darker.
TEST(implicit_lighting_gl, sh_transfer_from_the_realigned_normals_is_smoother_and_darker) {
    SYLVA_REQUIRE_GL();
    for (const char* representation : {"mesh_levels", "points_lines"}) {
        SCOPED_TRACE(representation);
        const crown_look sh = look_of("sh", representation);
        // k_a,min = 0, as above: the default's mild ambient would hardly tell a broken decode.
        const crown_look implicit = look_of("sh_implicit", representation, "photo", 1.0f, 0.0f);
        std::printf("%s: sh -> sh_implicit neighbour change %.2f -> %.2f, mean luma %.1f -> %.1f\n", representation,
                    sh.neighbour_change, implicit.neighbour_change, sh.mean_luma, implicit.mean_luma);
        // Measured 0.67x and 0.70x, and darker by 8.2 and 7.4 of 255; without k_a on the sky
        // (broken on purpose) 0.80x and 0.82x, darker by 6.8 and 6.1.
        EXPECT_LT(implicit.neighbour_change, 0.75 * sh.neighbour_change);
        EXPECT_LT(implicit.mean_luma, sh.mean_luma - 4.0);
    }
}

}  // namespace
}  // namespace sylva
