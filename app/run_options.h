#pragma once
// The options a run was started with, less those a shard sets for itself (which frames, where
// its output goes, how many threads): shards of one run must agree on the rest, and
// `sylva merge` refuses shards that do not (app/shard_merge.h).
#include <string>
#include <vector>

namespace sylva {

// Called once by main with the process's arguments.
void remember_run_options(int argc, const char* const* argv);
// The sub-command and its options, as given, without --frame-range, --shard, --out, --threads
// and their values (either as two words or as --option=value).
const std::vector<std::string>& run_options();
// For a message: the options joined by spaces.
std::string run_options_text(const std::vector<std::string>& options);

}  // namespace sylva
