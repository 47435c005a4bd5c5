// A bench configuration's figures from its per-frame records (summarize_records), by hand, and
// `sylva merge` of bench shards (issue 25): the merged report's figures are recomputed from the
// records, equal to the whole bench's; shards that do not make one bench are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "app/bench_catalogue.h"
#include "app/bench_measurements.h"
#include "app/bench_report.h"
#include "app/shard_merge.h"
#include "run_sylva.h"

namespace sylva {
namespace {

constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();

bench_frame frame(std::uint32_t f, std::vector<double> ms, double rmse, double ssim, double popping) {
    bench_frame r;
    r.frame = f;
    r.frame_ms = std::move(ms);
    r.rmse = rmse;
    r.ssim = ssim;
    r.perceptual = 0.1 * (f + 1);
    r.coverage_iou = 1.0;
    r.popping = popping;
    r.primitives = {{"triangles", 100.0 * (f + 1)}};
    return r;
}

bench_configuration three_frames(const std::string& name) {
    bench_configuration c;
    c.name = name;
    c.family = name;
    c.lighting = "normal";
    c.frame_records = {frame(0, {10, 20}, 0.1, 0.9, k_nan), frame(1, {30, 40}, 0.2, 0.8, 2.0),
                       frame(2, {50, 60}, 0.0, 0.7, 4.0)};
    // Windows end at most at frame 1: the first unchanged frame after one must be on the path.
    c.transition_records = {{5, 1, 0, 1, "fade", 4.0}, {3, 1, 0, 1, "switch", 2.0}, {4, 1, 0, 1, "fade", k_nan}};
    c.transitions_cut_off = 3;
    return c;
}

TEST(summarize_records, figures_from_the_records_by_hand) {
    bench_configuration c = three_frames("ladder");
    summarize_records(c);
    EXPECT_EQ(c.frames, 3u);
    // Round medians of (10, 30, 50) and (20, 40, 60); all six: (30 + 40) / 2.
    EXPECT_EQ(c.frame_ms_rounds, (std::vector<double>{30.0, 40.0}));
    EXPECT_DOUBLE_EQ(c.frame_ms_median, 35.0);
    EXPECT_DOUBLE_EQ(c.frame_ms_min, 10.0);
    EXPECT_DOUBLE_EQ(c.frame_ms_max, 60.0);
    // MSE (0.01 + 0.04 + 0) / 3 = 1/60: RMSE 0.129099, PSNR 10 log10(60) = 17.7815 dB.
    EXPECT_NEAR(c.error.rmse, 0.129099, 1e-6);
    EXPECT_NEAR(c.error.psnr_db, 17.7815, 1e-4);
    EXPECT_NEAR(c.error.ssim, 0.8, 1e-12);
    EXPECT_NEAR(c.error.perceptual, 0.2, 1e-12);
    EXPECT_DOUBLE_EQ(c.error.popping, 3.0);  // frame 0 has none
    EXPECT_DOUBLE_EQ(c.primitives.at("triangles"), 200.0);
    // Two transitions measured (jumps 2 and 4), one too small, three cut off.
    EXPECT_EQ(c.error.transitions, 2u);
    EXPECT_DOUBLE_EQ(c.error.lighting_jump, 3.0);
    EXPECT_EQ(c.error.transitions_too_small, 1u);
    EXPECT_EQ(c.error.transitions_cut_off, 3u);
    EXPECT_EQ(c.error.transition_frames, 2u);
    EXPECT_EQ(c.error.transitions_by_kind.at("switch"), 1u);
    EXPECT_EQ(c.error.transitions_by_kind.at("fade"), 1u);
}

// The whole bench of two configurations, and its two shards [0, 1) and [1, 3), as the runner
// writes them.
bench_report report_of(std::uint32_t first, std::uint32_t end, const std::string& host) {
    bench_report r;
    r.scenario = "tiny";
    r.source = "embedded:scenarios/tiny.json";
    r.machine = "cpu";
    r.gl_renderer = "llvmpipe";
    r.width = 64;
    r.height = 36;
    r.timing_rounds = 2;
    r.path_frames = 3;
    r.frames = end - first;
    r.range = {first, end, host, "cpu", 2, 1.0};
    r.lighting_families = {{"normal", "normal-mapped", 0.0, {}}};
    for (const char* name : {"baseline", "ladder"}) {
        bench_configuration c = three_frames(name);
        c.family = name;
        if (std::string(name) == "baseline") c.quality = k_named_baseline_distance_m;  // the family's baseline
        std::erase_if(c.frame_records, [&](const bench_frame& f) { return f.frame < first || f.frame >= end; });
        std::erase_if(c.transition_records,
                      [&](const bench_transition& t) { return t.to_frame + 1 < first || t.to_frame + 1 >= end; });
        c.transitions_cut_off = first == 0 ? 3 : 0;
        if (std::string(name) == "ladder")
            for (bench_frame& f : c.frame_records) f.frame_ms = {f.frame_ms[0] / 2, f.frame_ms[1] / 2};
        summarize_records(c);
        r.configurations.push_back(std::move(c));
        r.lighting_families[0].reference_frame_ms.push_back(1.0);
    }
    add_baseline_ratios(r);
    return r;
}

void write_shard(const std::filesystem::path& dir, const bench_report& r) {
    std::filesystem::create_directories(dir);
    write_bench_json(dir / "bench.json", r);
}

TEST(merge_bench_shards, recomputes_the_whole_benchs_figures_from_the_shards_records) {
    const auto dir = test::fresh_temp_dir("bench_merge");
    write_shard(dir / "b", report_of(1, 3, "node1"));
    write_shard(dir / "a", report_of(0, 1, "node1"));
    const merge_result result = merge_bench_shards({dir / "b", dir / "a"}, dir / "merged");
    EXPECT_EQ(result.shards, 2u);
    EXPECT_EQ(result.frames, 3u);
    const bench_report merged = read_bench_json(dir / "merged" / "bench.json");
    const bench_report whole = report_of(0, 3, "node1");
    ASSERT_EQ(merged.configurations.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        const bench_configuration& m = merged.configurations[i];
        const bench_configuration& w = whole.configurations[i];
        EXPECT_EQ(m.frame_records.size(), 3u);
        EXPECT_EQ(m.transition_records.size(), 3u);
        EXPECT_EQ(m.transitions_cut_off, 3u);
        bench_configuration again = m;
        summarize_records(again);
        EXPECT_EQ(again.error.ssim, w.error.ssim);  // bit for bit: the same sums in the same order
        EXPECT_EQ(again.error.psnr_db, w.error.psnr_db);
        EXPECT_EQ(again.error.lighting_jump, w.error.lighting_jump);
        EXPECT_EQ(again.frame_ms_rounds, w.frame_ms_rounds);
    }
    // One host: the ladder's time ratio is the whole bench's, 0.5.
    EXPECT_NEAR(merged.configurations[1].frame_ms_vs_baseline, 0.5, 1e-6);
    EXPECT_EQ(merged.shards.size(), 2u);
    std::filesystem::remove_all(dir);
}

TEST(merge_bench_shards, timings_of_two_hosts_give_a_ratio_per_host_and_none_across) {
    const auto dir = test::fresh_temp_dir("bench_merge_hosts");
    write_shard(dir / "a", report_of(0, 1, "node1"));
    write_shard(dir / "b", report_of(1, 3, "node2"));
    const merge_result result = merge_bench_shards({dir / "a", dir / "b"}, dir / "merged");
    EXPECT_EQ(result.hosts, (std::vector<std::string>{"node1 (2 threads)", "node2 (2 threads)"}));
    const bench_report merged = read_bench_json(dir / "merged" / "bench.json");
    const bench_configuration& ladder = merged.configurations[1];
    EXPECT_TRUE(std::isnan(ladder.frame_ms_vs_baseline));
    EXPECT_NEAR(ladder.frame_ms_vs_baseline_by_host.at("node1 (2 threads)"), 0.5, 1e-6);
    EXPECT_NEAR(ladder.frame_ms_vs_baseline_by_host.at("node2 (2 threads)"), 0.5, 1e-6);
    EXPECT_NE(merged.machine.find("several hosts"), std::string::npos) << merged.machine;
    std::filesystem::remove_all(dir);
}

TEST(merge_bench_shards, refuses_a_gap_an_overlap_and_shards_of_other_benches) {
    const auto dir = test::fresh_temp_dir("bench_merge_bad");
    write_shard(dir / "a", report_of(0, 1, "n"));
    write_shard(dir / "c", report_of(2, 3, "n"));
    write_shard(dir / "whole", report_of(0, 3, "n"));
    const auto message = [&](const std::vector<std::filesystem::path>& shards) {
        try {
            merge_bench_shards(shards, dir / "merged");
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message({dir / "a", dir / "c"}).find("frames 1 to 1 are in no shard"), std::string::npos);
    EXPECT_NE(message({dir / "a", dir / "whole"}).find("overlaps"), std::string::npos);
    EXPECT_NE(message({dir / "a"}).find("frames 1 to 2 of the path are in no bench shard"), std::string::npos);
    bench_report other = report_of(1, 3, "n");
    other.configurations.pop_back();
    write_shard(dir / "other", other);
    EXPECT_NE(message({dir / "a", dir / "other"}).find("configurations (--only)"), std::string::npos);
    EXPECT_NE(message({dir / "a", dir / "c"}).find(dir.string()), std::string::npos);  // names the shard
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sylva
