// Shards of a run (issue 25) through the command line: `play --frame-range` and `bench
// --frame-range` shards merged by `sylva merge` equal one whole run (frames byte for byte,
// per-frame hashes and records, every error figure; tests/slurm/compare_runs.py compares), for
// the ladder, points and lines, and a thread count other than the whole run's; bad ranges and
// merges are refused naming what is wrong.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "run_sylva.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

test::command_result compare(const std::string& kind, const fs::path& whole, const fs::path& merged) {
    return test::run_command("python3 " SYLVA_SOURCE_DIR "/tests/slurm/compare_runs.py " + kind + " " +
                             whole.string() + " " + merged.string());
}

void expect_play_shards_equal_whole(const std::string& options, const std::vector<std::string>& ranges) {
    const fs::path dir = test::fresh_temp_dir("play_shards");
    const auto whole = test::run_sylva("play " + options + " --headless --out " + (dir / "whole").string());
    ASSERT_EQ(whole.exit_code, 0) << whole.output;
    std::string shards;
    for (std::size_t k = 0; k < ranges.size(); ++k) {
        const fs::path out = dir / ("shard_" + std::to_string(k));
        // Every other shard on one thread: a shard equals the whole for any thread count.
        const auto r = test::run_sylva("play " + options + " --headless --frame-range " + ranges[k] +
                                       (k % 2 ? " --threads 1" : "") + " --out " + out.string());
        ASSERT_EQ(r.exit_code, 0) << r.output;
        shards += ' ';  // apart: GCC 12 warns falsely (-Wrestrict) on " " + a temporary
        shards += out.string();
    }
    const auto merged = test::run_sylva("merge" + shards + " --out " + (dir / "merged").string());
    ASSERT_EQ(merged.exit_code, 0) << merged.output;
    const auto same = compare("play", dir / "whole", dir / "merged");
    EXPECT_EQ(same.exit_code, 0) << same.output;
    fs::remove_all(dir);
}

TEST(shard_command, play_shards_of_the_ladder_merge_into_the_whole_run) {
    expect_play_shards_equal_whole("default --frames 6 --width 64 --height 36", {"0:2", "2:3", "3:"});
}

TEST(shard_command, play_shards_of_points_and_lines_merge_into_the_whole_run) {
    expect_play_shards_equal_whole("default --representation points_lines --primitive-budget 150000 --frames 5 --width 64 --height 36",
                                   {"0:2", "2:5"});
}

// The reference starts a shard without replaying (full geometry carries nothing over frames).
TEST(shard_command, reference_shards_merge_into_the_whole_reference) {
    expect_play_shards_equal_whole("tiny --reference --frames 4 --width 32 --height 18", {"0:1", "1:3", "3:4"});
}

TEST(shard_command, bench_shards_merge_into_the_whole_bench_with_its_transitions) {
    const fs::path dir = test::fresh_temp_dir("bench_shards");
    const std::string options = "bench default --frames 5 --width 48 --height 27 --only ladder,points_lines_budget_1m";
    ASSERT_EQ(test::run_sylva(options + " --out " + (dir / "whole").string()).exit_code, 0);
    ASSERT_EQ(test::run_sylva(options + " --shard 0/2 --out " + (dir / "a").string()).exit_code, 0);
    ASSERT_EQ(test::run_sylva(options + " --shard 1/2 --threads 1 --out " + (dir / "b").string()).exit_code, 0);
    const auto merged = test::run_sylva("merge " + (dir / "a").string() + " " + (dir / "b").string() + " --out " +
                                        (dir / "merged").string());
    ASSERT_EQ(merged.exit_code, 0) << merged.output;
    const auto same = compare("bench", dir / "whole", dir / "merged");
    EXPECT_EQ(same.exit_code, 0) << same.output;
    // Shard 1/2 holds frames 3 and 4; a transition it measured began before frame 2, so its
    // replay rendered an earlier frame for the colours there, and the reference's too
    // (bench_runner.cpp plan_replay, add_reference_colors).
    std::ifstream in(dir / "b" / "bench.json");
    const nlohmann::json shard = nlohmann::json::parse(in);
    bool begun_before = false;
    for (const auto& c : shard["configurations"])
        for (const auto& t : c["records"]["transitions"]) begun_before = begun_before || t["from_frame"] < 2;
    EXPECT_TRUE(begun_before) << "no transition of the second shard began before it: the planned replay went untested";
    // The compared files are really compared: a shard alone is not the whole bench.
    EXPECT_NE(compare("bench", dir / "whole", dir / "a").exit_code, 0);
    fs::remove_all(dir);
}

TEST(shard_command, bad_ranges_and_merges_exit_2_naming_what_is_wrong) {
    const fs::path dir = test::fresh_temp_dir("shard_errors");
    const auto beyond = test::run_sylva(
        "play tiny --representation mesh_levels --headless --frame-range 2:9 --out " +
        (dir / "x").string());
    EXPECT_EQ(beyond.exit_code, 2);
    EXPECT_NE(beyond.output.find("--frame-range 2:9"), std::string::npos) << beyond.output;
    EXPECT_FALSE(fs::exists(dir / "x"));
    const auto both = test::run_sylva("play tiny --headless --frame-range 0:2 --shard 0/2");
    EXPECT_EQ(both.exit_code, 2);
    // A frame-time target adapts to measured time: no shard of it can equal a whole run.
    const auto timed = test::run_sylva("play tiny --headless --representation ladder --target-frame-ms 30 "
                                       "--frame-range 1:3 --out " + (dir / "t").string());
    EXPECT_EQ(timed.exit_code, 2);
    EXPECT_NE(timed.output.find("frame-time target"), std::string::npos) << timed.output;
    EXPECT_FALSE(fs::exists(dir / "t"));

    const auto half = test::run_sylva(
        "play tiny --representation mesh_levels --headless --frames 4 "
        "--frame-range 0:2 --out " +
        (dir / "a").string());
    ASSERT_EQ(half.exit_code, 0) << half.output;
    const auto gap = test::run_sylva("merge " + (dir / "a").string() + " --out " + (dir / "m").string());
    EXPECT_EQ(gap.exit_code, 2);
    EXPECT_NE(gap.output.find("frames 2 to 3 of the path are in no shard"), std::string::npos) << gap.output;
    const auto into_shard = test::run_sylva("merge " + (dir / "a").string() + " --out " + (dir / "a").string());
    EXPECT_EQ(into_shard.exit_code, 2);
    EXPECT_TRUE(fs::exists(dir / "a" / "metrics.json"));
    const auto missing = test::run_sylva("merge " + (dir / "nowhere").string() + " --out " + (dir / "m").string());
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.output.find("nowhere"), std::string::npos) << missing.output;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
