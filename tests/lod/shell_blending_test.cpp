// Behrendt 2005 §3.3 (lod/shell_blending.h): premultiplied slices and the modified blending
// equation make a merged pyramid level blend like its slices one by one.
#include "lod/shell_blending.h"

#include <gtest/gtest.h>

#include <cmath>

#include "models/bake/shell_bake.h"
#include "models/bake/transfer_pages.h"

namespace sylva {
namespace {

void expect_rgb_near(const glm::vec4& a, const glm::vec4& b, float tolerance) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tolerance) << "channel " << k;
}

// c = (0.8, 0.4, 0.2, 0.5) over F = (0.1, 0.2, 0.3, 1): c • F = (0.45, 0.3, 0.25); c^pre =
// (0.4, 0.2, 0.1, 0.5) and c^pre ∘ F the same rgb; alpha 0.75 against 1 (the paper's ≈).
TEST(shell_blending, premultiplied_blending_equals_standard_blending_in_colour) {
    const glm::vec4 c{0.8f, 0.4f, 0.2f, 0.5f};
    const glm::vec4 f{0.1f, 0.2f, 0.3f, 1.0f};
    const glm::vec4 standard = blend_standard(c, f);
    const glm::vec4 modified = blend_premultiplied(premultiply(c), f);
    expect_rgb_near(standard, {0.45f, 0.3f, 0.25f, 0.0f}, 1e-6f);
    expect_rgb_near(modified, standard, 1e-6f);
    EXPECT_FLOAT_EQ(standard.a, 0.75f);  // 0.5·0.5 + 1·0.5
    EXPECT_FLOAT_EQ(modified.a, 1.0f);   // 0.5 + 1·0.5
}

// The pre-blended pair: (c0^pre ∘ c1^pre) ∘ F = c0 • (c1 • F) in colour, for hand-made colours;
// the same pair merged with the standard equation ((c0 • c1) • F) is off.
TEST(shell_blending, a_pre_blended_pair_blends_like_its_slices_one_by_one) {
    const glm::vec4 c0{0.9f, 0.7f, 0.1f, 0.6f};  // the upper slice
    const glm::vec4 c1{0.2f, 0.5f, 0.3f, 0.4f};  // the lower
    const glm::vec4 f{0.3f, 0.3f, 0.6f, 1.0f};
    const glm::vec4 one_by_one = blend_standard(c0, blend_standard(c1, f));
    const glm::vec4 merged = blend_premultiplied(blend_premultiplied(premultiply(c0), premultiply(c1)), f);
    expect_rgb_near(merged, one_by_one, 1e-6f);
    // By hand, red: c1 • F = 0.2·0.4 + 0.3·0.6 = 0.26; c0 • that = 0.9·0.6 + 0.26·0.4 = 0.644.
    EXPECT_NEAR(one_by_one.r, 0.644f, 1e-6f);
    const glm::vec4 standard_pair = blend_standard(blend_standard(c0, c1), f);
    EXPECT_GT(std::abs(standard_pair.r - one_by_one.r), 0.05f) << "the standard equation is not associative";
}

image_rgba8 flat(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) {
    image_rgba8 image;
    image.width = 2;
    image.height = 1;
    image.texels = {r, g, b, a, r, g, b, a};
    return image;
}

// A pyramid level of 8-bit premultiplied slices: pair (lower, upper) becomes upper ∘ lower, an
// odd slice is carried up; blending the merged slice over any frame equals blending the two one
// by one within 1/255 per channel.
TEST(shell_blending, a_pyramid_level_merges_pairs_within_one_step) {
    const std::vector<image_rgba8> slices = {flat(40, 60, 20, 100), flat(120, 30, 90, 200), flat(10, 10, 10, 30)};
    const std::vector<image_rgba8> level = next_pyramid_level(slices);
    ASSERT_EQ(level.size(), 2u);
    EXPECT_EQ(level[1].texels, slices[2].texels);
    // By hand: 120 + 40·(1 − 200/255) = 128.63 → 129; alpha 200 + 100·55/255 = 221.57 → 222.
    EXPECT_EQ(level[0].texels[0], 129);
    EXPECT_EQ(level[0].texels[3], 222);
    const auto to_float = [](const image_rgba8& i) {
        return glm::vec4(i.texels[0], i.texels[1], i.texels[2], i.texels[3]) / 255.0f;
    };
    for (const glm::vec4 frame : {glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), glm::vec4(1.0f), glm::vec4(0.2f, 0.7f, 0.4f, 1.0f)}) {
        const glm::vec4 one_by_one = blend_premultiplied(to_float(slices[1]), blend_premultiplied(to_float(slices[0]), frame));
        const glm::vec4 merged = blend_premultiplied(to_float(level[0]), frame);
        for (int k = 0; k < 4; ++k) EXPECT_LE(std::abs(merged[k] - one_by_one[k]), 1.0f / 255.0f) << k;
    }
}

// The pyramid a standard-equation renderer builds (measurement only): straight red at α 0.5
// under straight green at α 0.5, blended onto a cleared target: red • 0 = (0.5, 0, 0, 0.25), then
// green • that = (0, 0.5, 0, 0.25) + (0.5, 0, 0, 0.25)·0.5 = (0.25, 0.5, 0, 0.375), in 8 bits
// (64, 128, 0, 96). Over blue it shows (0.094, 0.19, 0.63), where the two slices one by one show
// (0.25, 0.5, 0.25): the colour shift §3.3 avoids with premultiplied slices.
TEST(shell_blending, the_standard_equations_pyramid_shifts_colours) {
    image_rgba8 lower, upper;
    lower.width = lower.height = upper.width = upper.height = 1;
    lower.texels = {255, 0, 0, 128};
    upper.texels = {0, 255, 0, 128};
    const image_rgba8 merged = merge_slices_standard(lower, upper);
    EXPECT_EQ(merged.texels, (std::vector<std::uint8_t>{64, 128, 0, 96}));
    const glm::vec4 blue{0.0f, 0.0f, 1.0f, 1.0f};
    const glm::vec4 m = glm::vec4(merged.texels[0], merged.texels[1], merged.texels[2], merged.texels[3]) / 255.0f;
    const glm::vec4 at_once = blend_standard(m, blue);
    const glm::vec4 one_by_one = blend_standard({0.0f, 1.0f, 0.0f, 128.0f / 255.0f}, blend_standard({1.0f, 0.0f, 0.0f, 128.0f / 255.0f}, blue));
    EXPECT_NEAR(at_once.b, 0.624f, 0.01f);
    EXPECT_NEAR(one_by_one.b, 0.249f, 0.01f);
    EXPECT_NEAR(one_by_one.r, 0.249f, 0.01f);
    // Straight colour back from the bake's premultiplied: (128, 0, 0, 128) is pure red.
    image_rgba8 pre = lower;
    pre.texels = {128, 0, 0, 128};
    EXPECT_EQ(unpremultiply_slice(pre).texels, (std::vector<std::uint8_t>{255, 0, 0, 128}));
    pre.texels = {0, 0, 0, 0};
    EXPECT_EQ(unpremultiply_slice(pre).texels, (std::vector<std::uint8_t>{0, 0, 0, 0}));
}

// One slice's transfer pages, every coefficient byte `value`, coverage byte `coverage`.
std::vector<image_rgba8> transfer_slice(std::uint8_t value, std::uint8_t coverage) {
    std::vector<image_rgba8> pages(k_transfer_pages, flat(value, value, value, value));
    for (image_rgba8& page : pages) page.width = 2;
    for (std::size_t t = 0; t < 2; ++t)
        pages[k_shell_transfer_coverage_channel / 4].texels[t * 4 + k_shell_transfer_coverage_channel % 4] = coverage;
    return pages;
}

// The slices' transfer merges like their normals, by coverage, upper over lower: upper bytes 200
// at coverage 128/255 = 0.502 over lower bytes 100 at full coverage: weights 0.502 and
// 1·(1 − 0.502) = 0.498, 200·0.502 + 100·0.498 = 150.2 → 150, coverage 1 → 255. Where neither
// is covered the upper's is kept (nothing shows it); an odd top slice is carried up.
TEST(shell_blending, a_pyramid_level_merges_the_transfer_by_coverage) {
    std::vector<image_rgba8> slices = transfer_slice(100, 255);
    for (const image_rgba8& page : transfer_slice(200, 128)) slices.push_back(page);
    for (const image_rgba8& page : transfer_slice(30, 7)) slices.push_back(page);
    const std::vector<image_rgba8> level = next_transfer_pyramid_level(slices);
    ASSERT_EQ(level.size(), 2 * k_transfer_pages);
    for (std::size_t c = 0; c < k_shell_transfer_coverage_channel; ++c)
        EXPECT_EQ(level[c / 4].texels[4 + c % 4], 150) << "coefficient " << c;
    EXPECT_EQ(level[k_shell_transfer_coverage_channel / 4].texels[4 + k_shell_transfer_coverage_channel % 4], 255);
    for (std::size_t p = 0; p < k_transfer_pages; ++p) EXPECT_EQ(level[k_transfer_pages + p].texels, slices[10 + p].texels);
    const std::vector<image_rgba8> bare = merge_transfer_slices(transfer_slice(90, 0), transfer_slice(170, 0));
    EXPECT_EQ(bare[0].texels[0], 170);
    EXPECT_EQ(bare[k_shell_transfer_coverage_channel / 4].texels[k_shell_transfer_coverage_channel % 4], 0);
    slices.pop_back();
    EXPECT_THROW(next_transfer_pyramid_level(slices), std::invalid_argument) << "not whole slices";
}

}  // namespace
}  // namespace sylva
