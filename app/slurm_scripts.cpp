#include "app/slurm_scripts.h"

namespace sylva {
namespace {

std::string header(const farm_plan& plan, const std::string& name, const std::string& log) {
    std::string s = "#!/usr/bin/env bash\n";
    s += "#SBATCH --job-name=" + name + "\n";
    s += "#SBATCH --output=" + (plan.out / "logs" / log).string() + "\n";
    s += "#SBATCH --cpus-per-task=" + std::to_string(plan.cpus_per_task) + "\n";
    s += "#SBATCH --ntasks=1\n";
    if (!plan.partition.empty()) s += "#SBATCH --partition=" + plan.partition + "\n";
    if (!plan.time_limit.empty()) s += "#SBATCH --time=" + plan.time_limit + "\n";
    if (!plan.memory.empty()) s += "#SBATCH --mem=" + plan.memory + "\n";
    s += "set -euo pipefail\n";
    s += "export SYLVA_CACHE_DIR=" + shell_quote(plan.cache.string()) + "\n";
    return s;
}

std::string options_text(const farm_plan& plan) {
    std::string s;
    for (const std::string& o : plan.options) {
        s += ' ';  // appended apart: GCC 12 warns falsely (-Wrestrict) on " " + a temporary string
        s += shell_quote(o);
    }
    return s;
}

}  // namespace

std::string shell_quote(const std::string& text) {
    const bool plain = !text.empty() && text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                               "0123456789_-+=./:,@%") == std::string::npos;
    if (plain) return text;
    std::string quoted = "'";
    for (const char c : text) {
        if (c == '\'')
            quoted += "'\\''";  // close, an escaped quote, open again
        else
            quoted += c;
    }
    quoted += '\'';
    return quoted;
}

std::string bake_script(const farm_plan& plan) {
    // The same command over frame 0 alone: every species bake, rung table and device calibration
    // the shards read is made here once, into the shared cache, rather than by N tasks side by
    // side (the cache's writes are atomic, so that would be correct, only N times the work).
    return header(plan, plan.job_name + "-bake", "bake.log") + "exec " + shell_quote(plan.sylva.string()) + " " +
           plan.command + " " + shell_quote(plan.scenario) + options_text(plan) + " --frame-range 0:1 --threads " +
           std::to_string(plan.cpus_per_task) + (plan.command == "play" ? " --headless" : "") + " --out " +
           shell_quote((plan.out / "bake").string()) + "\n";
}

std::string shard_script(const farm_plan& plan) {
    std::string s = header(plan, plan.job_name, "shard_%a.log");
    s.insert(s.find("#SBATCH --output"), "#SBATCH --array=0-" + std::to_string(plan.shards - 1) + "\n");
    const std::string shard_dir = shell_quote((plan.out / "shard_").string()) + "\"${SLURM_ARRAY_TASK_ID}\"";
    s += "exec " + shell_quote(plan.sylva.string()) + " " + plan.command + " " + shell_quote(plan.scenario) +
         options_text(plan) + " --shard \"${SLURM_ARRAY_TASK_ID}/" + std::to_string(plan.shards) + "\" --threads " +
         std::to_string(plan.cpus_per_task) + (plan.command == "play" ? " --headless" : "") + " --out " + shard_dir +
         "\n";
    return s;
}

std::string merge_script(const farm_plan& plan) {
    std::string s = header(plan, plan.job_name + "-merge", "merge.log");
    s += "exec " + shell_quote(plan.sylva.string()) + " merge";
    for (std::uint32_t k = 0; k < plan.shards; ++k) {
        s += ' ';
        s += shell_quote((plan.out / ("shard_" + std::to_string(k))).string());
    }
    s += " --out " + shell_quote((plan.out / "merged").string()) + "\n";
    return s;
}

std::string submit_script(const farm_plan& plan) {
    const auto script = [&](const char* name) { return shell_quote((plan.out / name).string()); };
    std::string s = "#!/usr/bin/env bash\n";
    s += "# Submits the bake job, the array of " + std::to_string(plan.shards) +
         " shards after it, and the merge after every shard succeeded.\n";
    s += "set -euo pipefail\n";
    s += "mkdir -p " + shell_quote((plan.out / "logs").string()) + "\n";
    s += "bake=$(sbatch --parsable " + script("bake.sbatch") + ")\n";
    // A failed job cancels the ones waiting for it, rather than leaving them pending forever.
    s += "shards=$(sbatch --parsable --kill-on-invalid-dep=yes --dependency=afterok:\"${bake%%;*}\" " +
         script("shards.sbatch") + ")\n";
    s += "merge=$(sbatch --parsable --kill-on-invalid-dep=yes --dependency=afterok:\"${shards%%;*}\" " +
         script("merge.sbatch") + ")\n";
    s += "echo \"bake ${bake%%;*} shards ${shards%%;*} merge ${merge%%;*}\"\n";
    return s;
}

}  // namespace sylva
