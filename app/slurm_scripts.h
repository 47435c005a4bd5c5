#pragma once
// The Slurm batch scripts `sylva farm` writes (issue 25): a bake job that fills the shared bake
// cache once, an array job with one task per shard (`play` or `bench` with --shard K/N), and a
// merge job that runs when every shard succeeded. Slurm schedules; nothing here stands in for it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sylva {

struct farm_plan {
    std::string command = "play";      // "play" or "bench"
    std::string scenario;              // as the command takes it (a file or a bundled name)
    std::vector<std::string> options;  // the command's own options, passed to every shard as given
    std::uint32_t shards = 1;
    std::filesystem::path out;         // shard_K/, merged/, logs/ and the scripts go here
    std::filesystem::path cache;       // SYLVA_CACHE_DIR of every job (a folder every node sees)
    std::filesystem::path sylva;       // the binary every node runs (a shared build, or the same path on each)
    std::string job_name;
    std::string partition;             // empty: the cluster's default
    std::string time_limit;            // per task, Slurm's format ("1:00:00"); empty: the default
    std::uint32_t cpus_per_task = 2;   // also the shard's --threads
    std::string memory;                // per task ("8G"); empty: the default
};

// Each script as text (bash with #SBATCH lines), arguments quoted for the shell.
std::string bake_script(const farm_plan& plan);
std::string shard_script(const farm_plan& plan);
std::string merge_script(const farm_plan& plan);
// Submits the three in order with their dependencies (sbatch --parsable, --dependency=afterok)
// and prints the job IDs; `sylva farm --submit` runs it, and so can anyone later.
std::string submit_script(const farm_plan& plan);

// `text` quoted for bash (single quotes), unless it needs none.
std::string shell_quote(const std::string& text);

}  // namespace sylva
