// Shell textures through the bake cache's bytes (models/cache/shell_stack_io.h): a round trip
// keeps the slices and their SH transfer pages, and damage is refused with a reason.
#include "models/cache/shell_stack_io.h"

#include <gtest/gtest.h>

#include "models/bake/transfer_pages.h"

namespace sylva {
namespace {

image_rgba8 filled(std::uint32_t side, std::uint8_t value) {
    image_rgba8 image;
    image.width = image.height = side;
    image.texels.assign(std::size_t(side) * side * 4, value);
    return image;
}

shell_stack stack_of(std::uint32_t slices, bool transfer) {
    shell_stack s;
    s.tile_size_m = 12.5;
    s.slice_height_m = 0.75f;
    for (std::uint32_t k = 0; k < slices; ++k) {
        s.colour.push_back(filled(8, std::uint8_t(10 + k)));
        s.normal.push_back(filled(8, std::uint8_t(100 + k)));
        for (std::uint32_t p = 0; transfer && p < k_transfer_pages; ++p) s.transfer.push_back(filled(2, std::uint8_t(k * 5 + p)));
    }
    return s;
}

TEST(shell_stack_io, a_round_trip_keeps_the_slices_and_their_transfer) {
    for (const bool transfer : {false, true}) {
        const std::vector<shell_stack> stacks = {stack_of(3, transfer), stack_of(3, transfer)};
        const std::vector<std::byte> bytes = serialize_shell_stacks(stacks);
        const std::vector<shell_stack> back = deserialize_shell_stacks(bytes);
        ASSERT_EQ(back.size(), 2u);
        EXPECT_EQ(back[1].tile_size_m, 12.5);
        EXPECT_EQ(back[1].slice_height_m, 0.75f);
        ASSERT_EQ(back[1].colour.size(), 3u);
        EXPECT_EQ(back[1].normal[2].texels, stacks[1].normal[2].texels);
        ASSERT_EQ(back[1].transfer.size(), transfer ? 3 * k_transfer_pages : 0u);
        if (transfer) EXPECT_EQ(back[1].transfer[7].texels, stacks[1].transfer[7].texels);
        EXPECT_EQ(serialize_shell_stacks(back), bytes);
    }
}

TEST(shell_stack_io, a_damaged_or_inconsistent_entry_is_refused) {
    const std::vector<shell_stack> stacks = {stack_of(2, true)};
    const std::vector<std::byte> bytes = serialize_shell_stacks(stacks);
    EXPECT_THROW(deserialize_shell_stacks(std::span(bytes).first(bytes.size() - 3)), std::runtime_error);
    std::vector<std::byte> version = bytes;
    version[4] = std::byte{1};  // a format-1 entry (before transfer) is a miss, never misread
    EXPECT_THROW(deserialize_shell_stacks(version), std::runtime_error);
    std::vector<shell_stack> short_pages = stacks;
    short_pages[0].transfer.pop_back();
    EXPECT_THROW(deserialize_shell_stacks(serialize_shell_stacks(short_pages)), std::runtime_error)
        << "9 pages for 2 slices";
    const std::vector<shell_stack> mixed = {stack_of(2, true), stack_of(2, false)};
    EXPECT_THROW(deserialize_shell_stacks(serialize_shell_stacks(mixed)), std::runtime_error)
        << "tiles with and without transfer";
}

}  // namespace
}  // namespace sylva
