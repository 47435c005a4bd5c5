#pragma once
// Joins the outputs of shards of one run (`--frame-range`, app/frame_range.h) into what the
// whole run writes (issue 25): `sylva play` shards into one metrics.json and frame folder,
// `sylva bench` shards into one bench report. Summaries are recomputed from the per-frame
// records, never averaged from the shards' summaries. Timings measured on different hosts are
// kept but marked, and never enter a time ratio.
#include <filesystem>
#include <string>
#include <vector>

namespace sylva {

struct merge_result {
    std::size_t shards = 0;
    std::size_t frames = 0;
    // Where the shards were timed, distinct, in shard order: hosts for play, host and thread
    // count for bench (its time ratios are per such domain).
    std::vector<std::string> hosts;
};

// Every shard folder holds a metrics.json (and its frame_NNNN images); the shards must be of
// one scenario, mode and set of options and together cover its path once, in contiguous
// ranges. Writes out/metrics.json and links (or copies) the frames into `out`, which must not
// be a shard's folder; an earlier merge's frames there are removed first.
// Throws std::invalid_argument naming the shard and what does not fit, std::runtime_error on
// file errors.
merge_result merge_play_shards(const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out);

// Every shard folder holds a bench.json written with per-frame records (`sylva bench
// --frame-range`, the same --only configurations and timing rounds); writes bench.json,
// bench.csv, bench.svg and summary.md into `out` as the whole bench does.
merge_result merge_bench_shards(const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out);

}  // namespace sylva
