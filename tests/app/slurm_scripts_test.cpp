// The Slurm scripts `sylva farm` writes (issue 25): quoting by hand, and what each job runs.
#include "app/slurm_scripts.h"

#include <gtest/gtest.h>

namespace sylva {
namespace {

farm_plan plan_of(const std::string& command) {
    farm_plan plan;
    plan.command = command;
    plan.scenario = "/data/my scenes/valley.json";
    plan.options = {"--frames", "100", "--only", "baseline,ladder"};
    plan.shards = 4;
    plan.out = "/shared/farm";
    plan.cache = "/shared/cache";
    plan.sylva = "/opt/sylva/bin/sylva";
    plan.job_name = "sylva-valley";
    plan.partition = "render";
    plan.cpus_per_task = 8;
    return plan;
}

TEST(slurm_scripts, shell_quote_leaves_plain_words_and_quotes_the_rest) {
    EXPECT_EQ(shell_quote("baseline,ladder"), "baseline,ladder");
    EXPECT_EQ(shell_quote("my scenes"), "'my scenes'");
    EXPECT_EQ(shell_quote("it's"), "'it'\\''s'");
    EXPECT_EQ(shell_quote(""), "''");
    EXPECT_EQ(shell_quote("$HOME"), "'$HOME'");
}

TEST(slurm_scripts, the_array_job_runs_one_shard_per_task_with_the_shared_cache) {
    const std::string s = shard_script(plan_of("bench"));
    EXPECT_NE(s.find("#SBATCH --array=0-3\n"), std::string::npos) << s;
    EXPECT_NE(s.find("#SBATCH --cpus-per-task=8\n"), std::string::npos) << s;
    EXPECT_NE(s.find("#SBATCH --partition=render\n"), std::string::npos) << s;
    EXPECT_NE(s.find("export SYLVA_CACHE_DIR=/shared/cache\n"), std::string::npos) << s;
    EXPECT_NE(s.find("/opt/sylva/bin/sylva bench '/data/my scenes/valley.json' --frames 100 --only baseline,ladder "
                     "--shard \"${SLURM_ARRAY_TASK_ID}/4\" --threads 8 --out /shared/farm/shard_\"${SLURM_ARRAY_TASK_ID}\""),
              std::string::npos)
        << s;
    EXPECT_EQ(s.find("--headless"), std::string::npos);  // bench has no such option
}

TEST(slurm_scripts, bake_runs_frame_0_and_merge_joins_every_shard_after_them) {
    const farm_plan plan = plan_of("play");
    EXPECT_NE(bake_script(plan).find(" --frame-range 0:1 --threads 8 --headless --out /shared/farm/bake"),
              std::string::npos);
    EXPECT_NE(merge_script(plan).find("merge /shared/farm/shard_0 /shared/farm/shard_1 /shared/farm/shard_2 "
                                      "/shared/farm/shard_3 --out /shared/farm/merged"),
              std::string::npos);
    const std::string submit = submit_script(plan);
    EXPECT_NE(submit.find("--kill-on-invalid-dep=yes --dependency=afterok:\"${bake%%;*}\" /shared/farm/shards.sbatch"),
              std::string::npos);
    EXPECT_NE(submit.find("--dependency=afterok:\"${shards%%;*}\" /shared/farm/merge.sbatch"), std::string::npos);
}

}  // namespace
}  // namespace sylva
