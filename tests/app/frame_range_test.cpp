// Frame ranges and shards (issue 25), by hand.
#include "app/frame_range.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace sylva {
namespace {

TEST(frame_range, parses_first_colon_end_and_an_open_end) {
    EXPECT_EQ(parse_frame_range("0:12", 48), (frame_range{0, 12}));
    EXPECT_EQ(parse_frame_range("40:", 48), (frame_range{40, 48}));
    EXPECT_EQ(parse_frame_range("47:48", 48).count(), 1u);
}

TEST(frame_range, refuses_what_names_no_frames_of_the_path_naming_the_value) {
    for (const char* bad : {"12", "5:5", "6:2", "0:49", "a:3", "-1:3", ":4", "1:2:3"}) {
        try {
            parse_frame_range(bad, 48);
            ADD_FAILURE() << bad << " accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(std::string("--frame-range ") + bad), std::string::npos) << e.what();
        }
    }
}

TEST(frame_range, shards_are_contiguous_and_the_first_ones_a_frame_longer) {
    // 10 frames over 4 shards: 10 = 4 * 2 + 2, so shards 0 and 1 hold 3 frames.
    EXPECT_EQ(shard_range(0, 4, 10), (frame_range{0, 3}));
    EXPECT_EQ(shard_range(1, 4, 10), (frame_range{3, 6}));
    EXPECT_EQ(shard_range(2, 4, 10), (frame_range{6, 8}));
    EXPECT_EQ(shard_range(3, 4, 10), (frame_range{8, 10}));
    EXPECT_EQ(parse_shard("1/4", 10), (frame_range{3, 6}));
    EXPECT_EQ(parse_shard("0/1", 10), (frame_range{0, 10}));
}

TEST(frame_range, refuses_bad_shards_and_both_options) {
    EXPECT_THROW(parse_shard("4/4", 10), std::invalid_argument);
    EXPECT_THROW(parse_shard("0/0", 10), std::invalid_argument);
    EXPECT_THROW(parse_shard("0/11", 10), std::invalid_argument);  // an empty shard
    EXPECT_THROW(parse_shard("1-4", 10), std::invalid_argument);
    EXPECT_THROW(range_asked("0:5", "0/2", 10), std::invalid_argument);
    EXPECT_EQ(range_asked("", "", 10), (frame_range{0, 10}));
}

}  // namespace
}  // namespace sylva
