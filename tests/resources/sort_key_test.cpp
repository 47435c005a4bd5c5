#include "resources/sort_key.h"

#include <gtest/gtest.h>

#include <random>

#include "resources/draw_list.h"

namespace sylva {
namespace {

TEST(sort_key, fields_round_trip_through_the_bit_layout) {
    const sort_key_fields in{render_pass::shadow_cascade_2, 0xBEEF, 0xABCDEF};
    const sort_key_fields out = decode_sort_key(make_sort_key(in));
    EXPECT_EQ(out.pass, in.pass);
    EXPECT_EQ(out.mesh, in.mesh);
    EXPECT_EQ(out.depth, in.depth);
}

TEST(sort_key, layout_matches_the_diagram) {
    // pass in bits 60..63, faded in 59, mesh in 43..58, depth in 19..42 (see the diagram in sort_key.h).
    EXPECT_EQ(make_sort_key({render_pass::opaque, 0, 0}), std::uint64_t(4) << 60);
    EXPECT_EQ(make_sort_key({render_pass::shadow_cascade_0, 0, 0, true}), std::uint64_t(1) << 59);
    EXPECT_EQ(make_sort_key({render_pass::shadow_cascade_0, 1, 0}), std::uint64_t(1) << 43);
    EXPECT_EQ(make_sort_key({render_pass::shadow_cascade_0, 0xFFFF, 0}), std::uint64_t(0xFFFF) << 43);
    EXPECT_EQ(make_sort_key({render_pass::shadow_cascade_0, 0, 1}), std::uint64_t(1) << 19);
    const sort_key_fields f = decode_sort_key(make_sort_key({render_pass::opaque, 0xABCD, 12345, true}));
    EXPECT_EQ(f.pass, render_pass::opaque);
    EXPECT_EQ(f.mesh, 0xABCD);
    EXPECT_EQ(f.depth, 12345u);
    EXPECT_TRUE(f.faded);
}

// A transition's dissolving partner is its own batch, drawn after every whole plant of the pass.
TEST(sort_key, faded_partners_batch_apart_after_the_whole_plants) {
    const auto whole_far = make_sort_key({render_pass::opaque, 0xFFFF, k_depth_max});
    const auto faded_near = make_sort_key({render_pass::opaque, 0, 0, true});
    EXPECT_LT(whole_far, faded_near);
    EXPECT_NE(batch_bits(make_sort_key({render_pass::opaque, 7, 10})),
              batch_bits(make_sort_key({render_pass::opaque, 7, 10, true})));
}

TEST(sort_key, pass_orders_before_mesh_before_depth) {
    const auto shadow_far = make_sort_key({render_pass::shadow_cascade_3, 0xFFFF, k_depth_max});
    const auto opaque_near = make_sort_key({render_pass::opaque, 0, 0});
    EXPECT_LT(shadow_far, opaque_near);
    const auto mesh1_far = make_sort_key({render_pass::opaque, 1, k_depth_max});
    const auto mesh2_near = make_sort_key({render_pass::opaque, 2, 0});
    EXPECT_LT(mesh1_far, mesh2_near);
}

TEST(sort_key, batch_bits_ignore_depth) {
    EXPECT_EQ(batch_bits(make_sort_key({render_pass::opaque, 7, 10})),
              batch_bits(make_sort_key({render_pass::opaque, 7, 99999})));
    EXPECT_NE(batch_bits(make_sort_key({render_pass::opaque, 7, 10})),
              batch_bits(make_sort_key({render_pass::opaque, 8, 10})));
}

TEST(sort_key, depth_quantisation_is_monotonic_and_saturates) {
    EXPECT_EQ(quantize_depth(0.0f), 0u);
    EXPECT_EQ(quantize_depth(0.1f), 0u);
    EXPECT_EQ(quantize_depth(1e9f), k_depth_max);
    std::uint32_t last = 0;
    for (float d = 0.2f; d < 1e5f; d *= 1.01f) {
        const std::uint32_t q = quantize_depth(d);
        EXPECT_GE(q, last);
        last = q;
    }
    // log2(100 m / 0.1 m) / 20 of the range: about half.
    EXPECT_NEAR(double(quantize_depth(100.0f)) / k_depth_max, std::log2(1000.0) / 20.0, 1e-6);
}

TEST(radix_sort, sorts_by_key_and_keeps_equal_keys_in_input_order) {
    std::mt19937_64 rng(5);
    std::vector<draw_item> items(10000);
    for (std::uint32_t i = 0; i < items.size(); ++i)
        items[i] = {make_sort_key({static_cast<render_pass>(rng() % 5), std::uint16_t(rng() % 4),
                                   std::uint32_t(rng() % 8)}),
                    i, 0};
    std::vector<draw_item> expected = items;
    std::stable_sort(expected.begin(), expected.end(),
                     [](const draw_item& a, const draw_item& b) { return a.key < b.key; });
    std::vector<draw_item> scratch;
    radix_sort_draw_items(items, scratch);
    for (std::size_t i = 0; i < items.size(); ++i) {
        ASSERT_EQ(items[i].key, expected[i].key) << i;
        ASSERT_EQ(items[i].instance, expected[i].instance) << i;
    }
}

TEST(radix_sort, handles_empty_single_and_all_equal_lists) {
    std::vector<draw_item> scratch;
    std::vector<draw_item> empty;
    radix_sort_draw_items(empty, scratch);
    EXPECT_TRUE(empty.empty());
    std::vector<draw_item> same(5, draw_item{42, 0, 0});
    for (std::uint32_t i = 0; i < 5; ++i) same[i].instance = i;
    radix_sort_draw_items(same, scratch);
    for (std::uint32_t i = 0; i < 5; ++i) EXPECT_EQ(same[i].instance, i);
}

}  // namespace
}  // namespace sylva
