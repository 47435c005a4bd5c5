#pragma once
// A shard of a run (issue 25): the frames [first, end) of a scenario's camera path, as
// `--frame-range A:B` names them. A shard writes exactly what the whole run writes for those
// frames (app/scenario_player.h replay_to reaches its first frame), and `sylva merge` joins
// shards into the whole run's outputs (app/merge_command.cpp).
#include <cstdint>
#include <optional>
#include <string>

namespace sylva {

struct frame_range {
    std::uint32_t first = 0;
    std::uint32_t end = 0;  // one past the last frame

    std::uint32_t count() const { return end - first; }
    bool contains(std::uint32_t frame) const { return frame >= first && frame < end; }
    bool operator==(const frame_range&) const = default;
};

// "A:B" (frames A to B - 1; "A:" runs to the path's end) within a path of `frames` frames.
// Throws std::invalid_argument naming the option, the value and what is wrong with it.
frame_range parse_frame_range(const std::string& text, std::uint32_t frames);

// The range of shard `shard` of `shards` over `frames` frames: contiguous, the first
// frames % shards shards one frame longer, in order (sylva farm's array tasks).
frame_range shard_range(std::uint32_t shard, std::uint32_t shards, std::uint32_t frames);

// "K/N": shard K (from 0) of N over `frames` frames (shard_range); `sylva farm`'s array tasks
// name their shard so, the path's length known only once the scenario is loaded. Throws
// std::invalid_argument naming the option and the value.
frame_range parse_shard(const std::string& text, std::uint32_t frames);

// The range a command's --frame-range or --shard asks for (at most one set), else every frame.
frame_range range_asked(const std::string& frame_range_text, const std::string& shard_text, std::uint32_t frames);

std::string to_string(const frame_range& range);  // "A:B"

}  // namespace sylva
