// What the last frame showed of each plant (resources/seen_pixels.h), on a hand-built draw
// list and ID buffer.
#include "resources/seen_pixels.h"

#include <gtest/gtest.h>

#include "resources/sort_key.h"
#include "setup/tile_point_sets.h"

namespace sylva {
namespace {

draw_item item(render_pass pass, std::uint32_t instance) {
    sort_key_fields f;
    f.pass = pass;
    return {make_sort_key(f), instance, 0};
}

TEST(seen_pixels, counts_each_plants_pixels_with_its_partner_and_without_tiles_or_shadow_draws) {
    draw_list draws;
    draws.items = {item(render_pass::shadow_cascade_0, 5),          // id 1: plant 5 casting only
                   item(render_pass::opaque, 2),                    // id 2: plant 2
                   item(render_pass::opaque, 2 | k_partner_item_bit),  // id 3: plant 2's old rung
                   item(render_pass::opaque, 0 | k_tile_item_bit),  // id 4: a tile's point set
                   item(render_pass::opaque, 0)};                   // id 5: plant 0
    // Two rows of four pixels; 0 is nothing, 6 is past the items (the terrain).
    const std::vector<std::uint32_t> ids{2, 2, 3, 0, 4, 5, 6, 2};
    seen_pixels seen;
    count_seen_pixels(ids, draws, seen);
    EXPECT_TRUE(seen.measured);
    EXPECT_EQ(seen.at(2), 4u);  // three of its rung, one of its partner
    EXPECT_EQ(seen.at(0), 1u);  // the tile's pixel is no plant's
    EXPECT_EQ(seen.at(5), 0u);
    EXPECT_TRUE(seen.drawn(2));
    EXPECT_TRUE(seen.drawn(0));
    EXPECT_FALSE(seen.drawn(5));  // only in a shadow map
    // What the solver is told: plant 2 showed 4 pixels; plant 5 was not in the view and a plant
    // beyond the counts was not drawn: not known (judged whole).
    EXPECT_FLOAT_EQ(shown_pixels(seen, 2), 4.0f);
    EXPECT_FLOAT_EQ(shown_pixels(seen, 0), 1.0f);
    EXPECT_FLOAT_EQ(shown_pixels(seen, 5), -1.0f);
    EXPECT_FLOAT_EQ(shown_pixels(seen, 99), -1.0f);
    // A frame later plant 2 is hidden: its count starts again from 0.
    const std::vector<std::uint32_t> hidden{5, 5, 5, 5, 5, 5, 5, 5};
    count_seen_pixels(hidden, draws, seen);
    EXPECT_EQ(seen.at(2), 0u);
    EXPECT_FLOAT_EQ(shown_pixels(seen, 2), 0.0f);
    // Not measured (no ID buffer): nothing known.
    seen.measured = false;
    EXPECT_FLOAT_EQ(shown_pixels(seen, 2), -1.0f);
}

}  // namespace
}  // namespace sylva
