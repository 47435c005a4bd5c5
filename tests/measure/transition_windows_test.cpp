// Transition windows on hand-built sequences of drawn mixes, and the lighting jump over them
// against values worked out by hand.
#include "measure/transition_windows.h"

#include <gtest/gtest.h>

namespace sylva {
namespace {

constexpr std::uint8_t k_a = 1, k_b = 2;

drawn_mix whole(std::uint8_t r, std::uint32_t plant = 0) {
    drawn_mix m;
    m.primary = r;
    m.group_first = plant;
    return m;
}

drawn_mix fading(std::uint8_t primary, std::uint8_t partner, float share, std::uint32_t plant = 0) {
    drawn_mix m = whole(primary, plant);
    m.partner = partner;
    m.share = share;
    return m;
}

drawn_mix in_group(std::uint32_t first, std::uint32_t count) {
    drawn_mix m;
    m.primary = 7;
    m.group_first = first;
    m.group_count = count;
    return m;
}

transition_finder one_plant(const std::vector<drawn_mix>& frames) {
    transition_finder finder(1);
    for (const drawn_mix& m : frames) finder.add_frame(std::span(&m, 1));
    return finder;
}

TEST(transition_finder, a_hard_switch_is_a_window_of_the_two_frames_around_it) {
    const auto finder =
        one_plant({whole(k_a), whole(k_a), whole(k_a), whole(k_b), whole(k_b), whole(k_b)});
    const auto windows = finder.complete_windows();
    ASSERT_EQ(windows.size(), 1u);
    EXPECT_EQ(windows[0].from_frame, 2u);
    EXPECT_EQ(windows[0].to_frame, 3u);
    EXPECT_EQ(windows[0].from, whole(k_a));
    EXPECT_EQ(windows[0].to, whole(k_b));
    EXPECT_FALSE(windows[0].partnered);
    EXPECT_EQ(finder.incomplete_windows(), 0u);
}

TEST(transition_finder, a_fade_is_one_window_over_the_whole_band) {
    // The flip of the primary (frame 4) is in the middle of the window, not its ends.
    const auto finder =
        one_plant({whole(k_a), whole(k_a), fading(k_a, k_b, 0.4f), fading(k_a, k_b, 0.9f),
                   fading(k_b, k_a, 0.6f), fading(k_b, k_a, 0.1f), whole(k_b), whole(k_b)});
    const auto windows = finder.complete_windows();
    ASSERT_EQ(windows.size(), 1u);
    EXPECT_EQ(windows[0].from_frame, 1u);
    EXPECT_EQ(windows[0].to_frame, 6u);
    EXPECT_TRUE(windows[0].partnered);
}

TEST(transition_finder, windows_the_path_cuts_off_are_incomplete) {
    // Changed between frames 0 and 1: the plant may have been changing before frame 0.
    EXPECT_TRUE(one_plant({whole(k_a), whole(k_b), whole(k_b)}).complete_windows().empty());
    EXPECT_EQ(one_plant({whole(k_a), whole(k_b), whole(k_b)}).incomplete_windows(), 1u);
    // Still changing at the last frame.
    const auto open =
        one_plant({whole(k_a), whole(k_a), fading(k_a, k_b, 0.2f), fading(k_a, k_b, 0.5f)});
    EXPECT_TRUE(open.complete_windows().empty());
    EXPECT_EQ(open.incomplete_windows(), 1u);
}

// Issue 25: a shard [first, end) keeps the windows whose end it saw (the first unchanged frame,
// to_frame + 1), so shards split the whole path's windows exactly, whatever the boundaries.
TEST(transition_finder, shards_split_the_windows_by_the_frame_that_shows_their_end) {
    // Frames 0..9: a switch seen ending at frame 4 (window 2..3) and a fade 5..8 seen ending at
    // frame 9 (window 5..8, from 5 since frame 6 is the first change).
    const std::vector<drawn_mix> path = {whole(k_a), whole(k_a), whole(k_a), whole(k_b), whole(k_b),
                                         whole(k_b), fading(k_b, k_a, 0.3f), fading(k_b, k_a, 0.6f),
                                         whole(k_a), whole(k_a)};
    const auto whole_path = one_plant(path).complete_windows();
    ASSERT_EQ(whole_path.size(), 2u);
    EXPECT_EQ(whole_path[0].to_frame, 3u);
    EXPECT_EQ(whole_path[1].from_frame, 5u);
    EXPECT_EQ(whole_path[1].to_frame, 8u);
    // Shard [4, 7) fed frames 0..6: it owns the switch (end seen at 4), not the fade (open).
    const auto shard = one_plant(std::vector<drawn_mix>(path.begin(), path.begin() + 7));
    std::vector<std::uint32_t> owned;
    for (const auto& w : shard.complete_windows())
        if (w.to_frame + 1 >= 4 && w.to_frame + 1 < 7) owned.push_back(w.to_frame);
    EXPECT_EQ(owned, std::vector<std::uint32_t>{3u});
    // The fade is open after frame 6, begun at frame 5: the next shard needs frame 5's colours.
    EXPECT_EQ(shard.open_from_frames(), std::vector<std::uint32_t>{5u});
    EXPECT_EQ(shard.open_windows(), 1u);
    // A window cut off at the path's start counts in the shard that saw it end.
    const auto cut = one_plant({whole(k_a), whole(k_b), whole(k_b), whole(k_b)});
    EXPECT_EQ(cut.cut_off_at_start_ending_in(0, 2), 0u);
    EXPECT_EQ(cut.cut_off_at_start_ending_in(2, 4), 1u);
}

TEST(transition_finder, a_band_left_the_way_it_was_entered_is_no_transition) {
    const auto finder =
        one_plant({whole(k_a), whole(k_a), fading(k_a, k_b, 0.3f), whole(k_a), whole(k_a)});
    EXPECT_TRUE(finder.complete_windows().empty());
    EXPECT_EQ(finder.returned_windows(), 1u);
}

TEST(transition_finder, entering_or_leaving_the_view_is_no_transition) {
    const auto finder = one_plant({whole(k_not_drawn), whole(k_not_drawn), whole(k_a), whole(k_a),
                                   whole(k_not_drawn), whole(k_not_drawn)});
    EXPECT_TRUE(finder.complete_windows().empty());
    EXPECT_EQ(finder.incomplete_windows(), 0u);
}

TEST(transition_finder, the_plants_of_an_eco_tile_hand_over_as_one_window_over_the_tile) {
    // Plants 0..2 form a tile; plants 0 and 2 are settled, plant 1 is fading since frame 1; at
    // frame 3 the tile's set takes all three over. One window for the tile, from frame 1.
    transition_finder finder(4);
    const std::vector<std::vector<drawn_mix>> frames = {
        {whole(k_a, 0), whole(k_a, 1), whole(k_a, 2), whole(k_a, 3)},
        {whole(k_a, 0), whole(k_a, 1), whole(k_a, 2), whole(k_a, 3)},
        {whole(k_a, 0), fading(k_a, k_b, 0.5f, 1), whole(k_a, 2), whole(k_a, 3)},
        {in_group(0, 3), in_group(0, 3), in_group(0, 3), whole(k_a, 3)},
        {in_group(0, 3), in_group(0, 3), in_group(0, 3), whole(k_a, 3)},
    };
    for (const auto& f : frames) finder.add_frame(f);
    const auto windows = finder.complete_windows();
    ASSERT_EQ(windows.size(), 1u);
    EXPECT_EQ(windows[0].first_plant, 0u);
    EXPECT_EQ(windows[0].plant_count, 3u);
    EXPECT_EQ(windows[0].from_frame, 1u);
    EXPECT_EQ(windows[0].to_frame, 3u);
    EXPECT_TRUE(windows[0].grouped);
    EXPECT_TRUE(windows[0].partnered);
}

TEST(transition_finder, rejects_a_frame_of_another_size) {
    transition_finder finder(2);
    const std::vector<drawn_mix> one(1);
    EXPECT_THROW(finder.add_frame(one), std::invalid_argument);
}

TEST(group_color, weighs_each_plant_by_its_pixels) {
    // Plant 0 (ID 1): 10 pixels of (100, 0, 0); plant 1 (ID 2): 30 pixels of (0, 100, 20); plant
    // 2 outside the group. Together: (25, 75, 15) over 40 pixels.
    const plant_colors colors{
        {1, {100, 0, 0, 10}}, {2, {0, 100, 20, 30}}, {3, {255, 255, 255, 99}}};
    const plant_color c = group_color(colors, 0, 2);
    EXPECT_EQ(c.pixels, 40u);
    EXPECT_DOUBLE_EQ(c.r, 25.0);
    EXPECT_DOUBLE_EQ(c.g, 75.0);
    EXPECT_DOUBLE_EQ(c.b, 15.0);
}

TEST(window_lighting_jump, is_the_colour_change_over_the_window_beyond_the_reference_change) {
    // Frames 0..2 of plant 0 (ID 1). Test: (100,100,100) at frame 0, (130,140,100) at frame 2;
    // reference: (90,90,90) then (96,98,90). Jump = |(30,40,0) - (6,8,0)| = |(24,32,0)| = 40.
    // Frame 1 (mid-fade) does not enter.
    const std::vector<plant_colors> test = {
        {{1, {100, 100, 100, 20}}}, {{1, {0, 0, 0, 20}}}, {{1, {130, 140, 100, 20}}}};
    const std::vector<plant_colors> reference = {
        {{1, {90, 90, 90, 20}}}, {{1, {0, 0, 0, 20}}}, {{1, {96, 98, 90, 20}}}};
    transition_window w;
    w.from_frame = 0;
    w.to_frame = 2;
    EXPECT_DOUBLE_EQ(window_lighting_jump(w, test, reference, 12), 40.0);
    // Too few pixels in one of the four: not measured.
    EXPECT_LT(window_lighting_jump(w, test, reference, 21), 0.0);
    w.to_frame = 3;
    EXPECT_THROW(window_lighting_jump(w, test, reference, 12), std::invalid_argument);
}

}  // namespace
}  // namespace sylva
