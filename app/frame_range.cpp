#include "app/frame_range.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace sylva {
namespace {

std::optional<std::uint32_t> parse_frame(const std::string& text) {
    std::uint32_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || text.empty()) return std::nullopt;
    return value;
}

}  // namespace

frame_range parse_frame_range(const std::string& text, std::uint32_t frames) {
    const auto fail = [&](const std::string& why) {
        return std::invalid_argument("--frame-range " + text + ": " + why);
    };
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos) throw fail("expected FIRST:END (frames FIRST to END - 1, e.g. 0:12)");
    const auto first = parse_frame(text.substr(0, colon));
    const std::string end_text = text.substr(colon + 1);
    const auto end = end_text.empty() ? std::optional<std::uint32_t>(frames) : parse_frame(end_text);
    if (!first || !end) throw fail("FIRST and END must be whole frame numbers");
    if (*first >= *end) throw fail("FIRST must be below END");
    if (*end > frames)
        throw fail("the scenario plays " + std::to_string(frames) + " frames (0 to " + std::to_string(frames) +
                   " - 1); END may be at most " + std::to_string(frames));
    return {*first, *end};
}

frame_range shard_range(std::uint32_t shard, std::uint32_t shards, std::uint32_t frames) {
    if (shards == 0 || shard >= shards) throw std::invalid_argument("shard_range: shard " + std::to_string(shard) +
                                                                    " of " + std::to_string(shards));
    const std::uint32_t base = frames / shards, longer = frames % shards;
    const std::uint32_t first = shard * base + std::min(shard, longer);
    return {first, first + base + (shard < longer ? 1u : 0u)};
}

frame_range parse_shard(const std::string& text, std::uint32_t frames) {
    const std::size_t slash = text.find('/');
    const auto shard = slash == std::string::npos ? std::nullopt : parse_frame(text.substr(0, slash));
    const auto shards = slash == std::string::npos ? std::nullopt : parse_frame(text.substr(slash + 1));
    if (!shard || !shards || *shards == 0)
        throw std::invalid_argument("--shard " + text + ": expected K/N, shard K (from 0) of N, e.g. 0/4");
    if (*shard >= *shards)
        throw std::invalid_argument("--shard " + text + ": K must be below N (shards are numbered 0 to N - 1)");
    if (*shards > frames)
        throw std::invalid_argument("--shard " + text + ": " + std::to_string(*shards) + " shards of a path of " +
                                    std::to_string(frames) + " frames would leave some empty");
    return shard_range(*shard, *shards, frames);
}

frame_range range_asked(const std::string& frame_range_text, const std::string& shard_text, std::uint32_t frames) {
    if (!frame_range_text.empty() && !shard_text.empty())
        throw std::invalid_argument("--frame-range and --shard name the frames twice: give one");
    if (!frame_range_text.empty()) return parse_frame_range(frame_range_text, frames);
    if (!shard_text.empty()) return parse_shard(shard_text, frames);
    return {0, frames};
}

std::string to_string(const frame_range& range) {
    return std::to_string(range.first) + ":" + std::to_string(range.end);
}

}  // namespace sylva
