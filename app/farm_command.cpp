// `sylva farm`: runs a play or a bench as a Slurm array job, one task per shard of the camera
// path, and merges the shards when every task succeeded (issue 25; app/slurm_scripts.h).
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "app/commands.h"
#include "app/frame_range.h"
#include "app/slurm_scripts.h"
#include "app/scenario_options.h"
#include "io/atomic_file.h"

namespace sylva {
namespace {

struct farm_options {
    farm_plan plan;
    std::string out_dir = "out/farm";
    std::string cache_dir;
    std::string sylva;
    bool submit = false;
};

std::filesystem::path this_binary() {
    std::error_code ec;
    const auto path = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path("sylva") : path;
}

bool sbatch_available() { return std::system("command -v sbatch >/dev/null 2>&1") == 0; }

void write_script(const std::filesystem::path& path, const std::string& text) {
    write_atomically(path, text);
    std::filesystem::permissions(path, std::filesystem::perms::owner_exec | std::filesystem::perms::group_exec,
                                 std::filesystem::perm_options::add);
}

int farm(farm_options o) {
    farm_plan& plan = o.plan;
    if (plan.command != "play" && plan.command != "bench") {
        spdlog::error("farm: the command must be play or bench, not '{}'", plan.command);
        return k_exit_bad_input;
    }
    // The path's length decides nothing here (each task finds its frames from --shard K/N), but
    // a scenario that does not load, or more shards than frames, is refused before anything is
    // written or submitted.
    scenario_options so;
    so.path = plan.scenario;
    for (std::size_t i = 0; i < plan.options.size(); ++i) {
        const std::string& option = plan.options[i];
        if (option == "--frames" && i + 1 < plan.options.size())
            so.frames = std::uint32_t(std::strtoul(plan.options[i + 1].c_str(), nullptr, 10));
        if (option.rfind("--frames=", 0) == 0) so.frames = std::uint32_t(std::strtoul(option.c_str() + 9, nullptr, 10));
    }
    const std::optional<scenario> loaded = load_or_report(so);
    if (!loaded) return k_exit_bad_input;
    try {
        (void)parse_shard(std::to_string(plan.shards - 1) + "/" + std::to_string(plan.shards), loaded->frames);
    } catch (const std::invalid_argument& e) {
        spdlog::error("farm: {}", e.what());
        return k_exit_bad_input;
    }
    for (const std::string& option : plan.options)
        if (option == "--target-frame-ms" || option.rfind("--target-frame-ms=", 0) == 0) {
            spdlog::error("farm: {} adapts to each node's measured time: no shard of such a run equals the whole, so "
                          "it cannot be farmed (a --plant-budget-ms or --max-error run can)",
                          option);
            return k_exit_bad_input;
        }
    for (const std::string& option : plan.options)
        for (const char* own : {"--frame-range", "--shard", "--out", "--threads"})
            if (option == own || option.rfind(std::string(own) + "=", 0) == 0) {
                spdlog::error("farm: {} is the farm's to set for each task (--cpus-per-task sets --threads)", option);
                return k_exit_bad_input;
            }
    plan.out = std::filesystem::absolute(o.out_dir);
    plan.cache = std::filesystem::absolute(!o.cache_dir.empty()               ? std::filesystem::path(o.cache_dir)
                                           : std::getenv("SYLVA_CACHE_DIR") ? std::getenv("SYLVA_CACHE_DIR")
                                                                             : plan.out / "cache");
    plan.sylva = o.sylva.empty() ? this_binary() : std::filesystem::absolute(o.sylva);
    // A scenario file is named by its absolute path: the tasks start elsewhere.
    if (std::filesystem::exists(plan.scenario)) plan.scenario = std::filesystem::absolute(plan.scenario).string();
    if (plan.job_name.empty()) {
        plan.job_name = "sylva-" + loaded->name;
        for (char& c : plan.job_name)
            if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '-';
    }
    // #SBATCH lines take one word each, and Slurm expands % in file names.
    for (const auto& [what, text] : {std::pair<const char*, std::string>{"--out", std::filesystem::absolute(o.out_dir).string()},
                                {"--job-name", plan.job_name}})
        if (text.find_first_of(" \t\n%'\"") != std::string::npos) {
            spdlog::error("farm: {} {}: no spaces, quotes or % (the batch scripts' #SBATCH lines cannot hold them)",
                          what, text);
            return k_exit_bad_input;
        }
    try {
        std::filesystem::create_directories(plan.out / "logs");
        std::filesystem::create_directories(plan.cache);
        write_script(plan.out / "bake.sbatch", bake_script(plan));
        write_script(plan.out / "shards.sbatch", shard_script(plan));
        write_script(plan.out / "merge.sbatch", merge_script(plan));
        write_script(plan.out / "submit.sh", submit_script(plan));
    } catch (const std::exception& e) {
        spdlog::error("farm: {}", e.what());
        return k_exit_failure;
    }
    spdlog::info("wrote {0}/bake.sbatch, shards.sbatch ({1} tasks), merge.sbatch and submit.sh; the merged output "
                 "({2}) will be in {0}/merged",
                 plan.out.string(), plan.shards, plan.command == "play" ? "frames and metrics.json" : "bench.json and its tables");
    if (!o.submit) {
        spdlog::info("submit with: {}", (plan.out / "submit.sh").string());
        return k_exit_ok;
    }
    if (!sbatch_available()) {
        spdlog::error("farm --submit: sbatch is not on the PATH (is this a Slurm login node?); the scripts are "
                      "written, submit them from one with {}",
                      (plan.out / "submit.sh").string());
        return k_exit_failure;
    }
    const int status = std::system(shell_quote((plan.out / "submit.sh").string()).c_str());
    if (status != 0) {
        spdlog::error("farm: submitting failed (sbatch's message is above)");
        return k_exit_failure;
    }
    spdlog::info("submitted; logs in {}/logs, the merge runs when every shard succeeded", plan.out.string());
    return k_exit_ok;
}

}  // namespace

command_runner add_farm_command(CLI::App& app) {
    auto options = std::make_shared<farm_options>();
    app.add_option("command", options->plan.command, "What each task runs: play or bench")
        ->required()
        ->check(CLI::IsMember({"play", "bench"}));
    app.add_option("scenario", options->plan.scenario, "Scenario file, or a bundled scenario's name")->required();
    app.add_option("--shards", options->plan.shards, "Tasks of the array job, each a contiguous range of frames")
        ->required()
        ->check(CLI::Range(1u, 100000u));
    app.add_option("--out", options->out_dir,
                   "Folder every node sees: the scripts, logs/, shard_K/ and merged/ (the merged output)")
        ->capture_default_str();
    app.add_option("--cache", options->cache_dir,
                   "Bake cache every node sees (SYLVA_CACHE_DIR of each job); default $SYLVA_CACHE_DIR, else "
                   "OUT/cache");
    app.add_option("--sylva", options->sylva,
                   "The sylva binary each node runs: a shared build, or one built at the same path on every "
                   "node (default: this binary)");
    app.add_option("--job-name", options->plan.job_name, "Slurm job name (default sylva-SCENARIO)");
    app.add_option("--partition", options->plan.partition, "Slurm partition (default: the cluster's)");
    app.add_option("--time", options->plan.time_limit, "Time limit of each task, as Slurm writes it (1:00:00)");
    app.add_option("--mem", options->plan.memory, "Memory of each task, as Slurm writes it (8G)");
    app.add_option("--cpus-per-task", options->plan.cpus_per_task, "CPUs of each task, and its --threads")
        ->capture_default_str()
        ->check(CLI::Range(1u, 4096u));
    app.add_flag("--submit", options->submit,
                 "Submit the jobs with sbatch (bake, then the shards, then the merge, each after the one before "
                 "succeeded); without it the scripts are only written");
    app.add_option("options", options->plan.options,
                   "After --: the play or bench options every task passes on (e.g. -- --frames 100 --width 1920 "
                   "--only baseline,ladder --timing-rounds 3)");
    app.footer(
        "What the cluster needs: Sylva built on every node (a shared build folder, or the same path on "
        "each; --sylva), with Mesa's OSMesa (libosmesa6) for headless GL, since the tasks have no display; "
        "an --out and --cache folder every node reads and writes (NFS or similar); Slurm's sbatch. The "
        "first job runs the command over frame 0 alone to fill the bake cache once; each array task then "
        "plays or benches its shard (--shard K/N, bit for bit the whole run's frames: `sylva play --help`), "
        "and the last job runs `sylva merge`. Frame times of tasks on different nodes are kept apart: a "
        "bench's time ratios are per node.");
    return [options] { return farm(*options); };
}

}  // namespace sylva
