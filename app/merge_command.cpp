// `sylva merge`: joins the outputs of shards of one run (`play --frame-range`, `bench
// --frame-range`, `sylva farm`'s array tasks) into what the whole run writes.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>

#include "app/commands.h"
#include "app/shard_merge.h"

namespace sylva {
namespace {

struct merge_options {
    std::vector<std::string> shards;
    std::string out_dir;
};

int merge(const merge_options& o) {
    std::vector<std::filesystem::path> dirs;
    for (const std::string& s : o.shards) {
        if (!std::filesystem::is_directory(s)) {
            spdlog::error("merge: shard folder {} {}", s,
                          std::filesystem::exists(s) ? "is not a folder" : "does not exist");
            return k_exit_bad_input;
        }
        dirs.emplace_back(s);
    }
    const auto holds = [&](const char* file) {
        return std::all_of(dirs.begin(), dirs.end(), [&](const auto& d) { return std::filesystem::exists(d / file); });
    };
    try {
        if (holds("metrics.json")) {
            const merge_result r = merge_play_shards(dirs, o.out_dir);
            spdlog::info("merged {} play shards, {} frames, into {}/metrics.json{}", r.shards, r.frames, o.out_dir,
                         r.hosts.size() > 1 ? " (timed on " + std::to_string(r.hosts.size()) + " hosts)" : "");
            return k_exit_ok;
        }
        if (holds("bench.json")) {
            const merge_result r = merge_bench_shards(dirs, o.out_dir);
            spdlog::info("merged {} bench shards, {} frames, into {}{}", r.shards, r.frames, o.out_dir,
                         r.hosts.size() > 1 ? " (timed on " + std::to_string(r.hosts.size()) +
                                                  " hosts: no time ratios across them)"
                                            : "");
            return k_exit_ok;
        }
        spdlog::error("merge: every shard folder must hold a metrics.json (sylva play) or every one a bench.json "
                      "(sylva bench); {} does not", [&] {
                          for (const auto& d : dirs)
                              if (!std::filesystem::exists(d / "metrics.json") && !std::filesystem::exists(d / "bench.json"))
                                  return d.string();
                          return std::string("a mix of play and bench shards");
                      }());
        return k_exit_bad_input;
    } catch (const std::invalid_argument& e) {
        spdlog::error("merge: {}", e.what());
        return k_exit_bad_input;
    } catch (const std::exception& e) {
        spdlog::error("merge: {}", e.what());
        return k_exit_failure;
    }
}

}  // namespace

command_runner add_merge_command(CLI::App& app) {
    auto options = std::make_shared<merge_options>();
    app.add_option("shards", options->shards,
                   "Shard output folders of one run, in any order: each a `sylva play --frame-range` --out "
                   "(metrics.json and frames) or a `sylva bench --frame-range` --out (bench.json)")
        ->required();
    app.add_option("--out", options->out_dir,
                   "Folder for the merged output: metrics.json and the frames, or bench.json, bench.csv, "
                   "bench.svg and summary.md, as the whole run writes them")
        ->required();
    app.footer(
        "Summaries (medians, means, errors, transitions) are recomputed from the shards' per-frame "
        "records, so they are the whole run's, not averages of the shards'. Shards must cover the "
        "camera path once, in contiguous frame ranges, with the same scenario, size, renderer and "
        "configurations. Frame times of shards timed on different hosts (or thread counts) are kept "
        "and marked; a bench's time ratios then come per host, from the frames it timed, where each "
        "configuration ran side by side with its baseline.");
    return [options] { return merge(*options); };
}

}  // namespace sylva
