// `sylva bench`: every configuration over the scenario's camera path, side by side in one
// process, against the supersampled full-geometry reference; writes bench.json, bench.csv,
// bench.svg and summary.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <spdlog/spdlog.h>

#include "app/bench_catalogue.h"
#include "app/bench_report.h"
#include "app/bench_runner.h"
#include "app/bench_verdict.h"
#include "app/commands.h"
#include "app/frame_range.h"
#include "app/run_options.h"
#include "app/interrupt.h"
#include "app/scenario_options.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

struct bench_options {
    scenario_options scenario;
    std::string out_dir = "out/bench";
    std::vector<std::string> only;
    bool list = false;
    bool save_frames = false;
    std::uint32_t timing_rounds = 1;
    std::string frame_range;  // "A:B": a shard (app/frame_range.h)
    std::string shard;        // "K/N": the same, as shard K of N
};

// Frames and size a bench plays unless told otherwise: a quarter of the scenario's pixels
// (the reference renders 9 times as many, at full geometry, on a CPU rasteriser).
constexpr std::uint32_t k_default_bench_width = 480;
constexpr std::uint32_t k_default_bench_height = 270;

void print_progress(const std::vector<bench_configuration_spec>& specs,
                    const std::vector<std::string>& only, const bench_progress& p) {
    std::string name = "reference (" + p.reference_lighting + ")";
    if (p.configuration >= 0) {
        std::size_t seen = 0;
        for (const auto& s : specs)
            if (only.empty() || std::find(only.begin(), only.end(), s.name) != only.end()) {
                if (seen++ == std::size_t(p.configuration)) name = s.name;
            }
    }
    if (p.rounds > 1 && p.round > 0)
        std::fprintf(stderr, "\r[sylva] bench timing round %u/%u %-26s frame %u/%u   ", p.round + 1,
                     p.rounds, name.c_str(), p.frame + 1, p.frames);
    else
        std::fprintf(stderr, "\r[sylva] bench %d/%zu %-26s frame %u/%u   ", p.configuration + 2,
                     p.configurations + 1, name.c_str(), p.frame + 1, p.frames);
    if (p.frame + 1 == p.frames) std::fprintf(stderr, "\n");
}

// The table and the verdicts on stdout, after the files are written.
void print_results(const bench_report& report) {
    std::printf("%-28s %-8s %10s %9s %9s %8s %8s %8s %8s %8s %6s\n", "configuration", "lighting", "median ms",
                "x base", "PSNR dB", "SSIM", "FLIP", "IoU", "popping", "jump", "trans");
    for (const auto& c : report.configurations) {
        const std::string jump =
            std::isfinite(c.error.lighting_jump) ? std::to_string(c.error.lighting_jump).substr(0, 6) : "n/a";
        std::printf("%-28s %-8s %10.1f %9.3f %9.2f %8.4f %8.4f %8.4f %8.3f %8s %6llu\n", c.name.c_str(),
                    c.lighting.c_str(), c.frame_ms_median, c.frame_ms_vs_baseline, c.error.psnr_db, c.error.ssim,
                    c.error.perceptual, c.error.coverage_iou, c.error.popping, jump.c_str(),
                    static_cast<unsigned long long>(c.error.transitions));
    }
    const std::vector<family_verdict> verdicts = baseline_verdicts(report);
    if (verdicts.empty()) return;
    std::printf("\nVerdict: does each sweep beat the engine baseline's (time ratio <= 1, SSIM >=, FLIP <=)?\n");
    for (const family_verdict& v : verdicts) {
        std::printf("  %-8s %-22s %s\n", v.lighting.c_str(), v.family.c_str(), v.summary().c_str());
        for (const baseline_point_verdict& p : v.points)
            if (p.beaten_by.empty())
                std::printf("  %-31s   %s: %s\n", "", p.baseline.c_str(), p.why_not.c_str());
            else
                std::printf("  %-31s   %s: beaten by %s (%.2fx)\n", "", p.baseline.c_str(), p.beaten_by.c_str(),
                            p.time_ratio);
    }
}

int bench(const bench_options& o) {
    auto specs = default_bench_configurations();
    if (o.list) {
        for (const auto& c : specs) std::printf("%-28s %s\n", c.name.c_str(), c.description.c_str());
        return k_exit_ok;
    }
    scenario_options so = o.scenario;
    if (!so.width && !so.height) {
        so.width = k_default_bench_width;
        so.height = k_default_bench_height;
    }
    const std::optional<scenario> loaded = load_or_report(so);
    if (!loaded) return k_exit_bad_input;
    const scenario& s = *loaded;
    std::optional<frame_range> range;
    try {
        if (!o.frame_range.empty() || !o.shard.empty()) range = range_asked(o.frame_range, o.shard, s.frames);
    } catch (const std::invalid_argument& e) {
        spdlog::error("{}", e.what());
        return k_exit_bad_input;
    }
    // The representation options ask for one more configuration: what `play` draws with them.
    std::vector<std::string> only = o.only;
    // Configurations that would draw what another does on this scenario are left out unless named.
    std::erase_if(specs, [&](const bench_configuration_spec& c) {
        return !applies_to(c, s) && std::find(only.begin(), only.end(), c.name) == only.end();
    });
    try {
        if (const auto extra = command_line_configuration(s, so)) {
            const bool known = std::any_of(specs.begin(), specs.end(), [&](const auto& c) { return c.name == extra->name; });
            if (!known) specs.push_back(*extra);
            if (!only.empty() && std::find(only.begin(), only.end(), extra->name) == only.end())
                only.push_back(extra->name);
            spdlog::info("measuring '{}' from the command line beside the others", extra->name);
        }
    } catch (const std::invalid_argument& e) {
        spdlog::error("{}", e.what());
        return k_exit_bad_input;
    }
    std::error_code ec;
    std::filesystem::create_directories(o.out_dir, ec);
    if (ec) {
        spdlog::error("cannot create the output folder {}: {}", o.out_dir, ec.message());
        return k_exit_bad_input;
    }
    const interrupt_guard interrupts;
    try {
        render::context_options context_options;
        context_options.width = 64;  // every player renders into its own framebuffer
        context_options.height = 64;
        context_options.headless = true;
        auto context = render::create_context(context_options);
        spdlog::info("bench '{}': {} frames at {}x{}, reference {}x{} samples per pixel, on {}", s.name, s.frames,
                     s.width, s.height, k_bench_reference_samples, k_bench_reference_samples, context->renderer());
        bake_cache cache;
        bench_settings settings;
        settings.threads = o.scenario.threads;
        settings.only = only;
        if (o.save_frames) settings.frames_dir = std::filesystem::path(o.out_dir) / "frames";
        settings.timing_rounds = o.timing_rounds;
        settings.range = range;
        settings.progress = [&](const bench_progress& p) { print_progress(specs, only, p); };
        settings.stop = interrupt_requested;
        const auto start = std::chrono::steady_clock::now();
        bench_report report = run_bench(s, specs, *context, &cache, settings);
        report.options = run_options();
        const std::filesystem::path dir(o.out_dir);
        write_bench_json(dir / "bench.json", report);
        write_bench_csv(dir / "bench.csv", report);
        write_bench_plot_svg(dir / "bench.svg", report);
        write_bench_summary_md(dir / "summary.md", report);
        if (report.partial) {
            spdlog::warn("interrupted by {}: wrote what was measured ({} configurations) to {}, marked partial",
                         interrupt_signal_name(), report.configurations.size(), o.out_dir);
            return interrupt_exit_code();
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        print_results(report);
        spdlog::info("wrote bench.json, bench.csv, bench.svg and summary.md to {} in {:.0f} s", o.out_dir, seconds);
    } catch (const std::invalid_argument& e) {
        spdlog::error("{}", e.what());
        return k_exit_bad_input;
    } catch (const scenario_error& e) {  // a file the scenario names cannot be used
        spdlog::error("{}", e.what());
        return k_exit_bad_input;
    } catch (const std::exception& e) {
        spdlog::error("{}", e.what());
        return k_exit_failure;
    }
    return k_exit_ok;
}

}  // namespace

command_runner add_bench_command(CLI::App& app) {
    auto options = std::make_shared<bench_options>();
    add_scenario_options(app, options->scenario);
    app.add_option("--out", options->out_dir, "Output folder for bench.json, bench.csv, bench.svg and summary.md")
        ->capture_default_str();
    app.add_option("--only", options->only,
                   "Run only these configurations (comma-separated names; see --list). The reference of "
                   "each lighting they use is always rendered: every error is measured against it")
        ->delimiter(',');
    app.add_option(
           "--timing-rounds", options->timing_rounds,
           "Play every configuration's frames this many times for its timing, the "
           "configurations alternating round by round, and report medians over all rounds and "
           "each configuration's time against the baseline as the median of the round-by-round "
           "ratios. Errors come from the first round; the reference is timed in it only. Use on "
           "a noisy machine to compare times")
        ->capture_default_str()
        ->check(CLI::Range(1u, 1000u));
    app.add_option("--frame-range", options->frame_range,
                   "Measure only frames FIRST to END - 1 of the camera path (FIRST:END), exactly as the whole "
                   "bench measures them (every player replays the frames before; the reference's are "
                   "rendered where a transition began); bench.json keeps per-frame records, and `sylva "
                   "merge` joins shards into the whole bench's outputs")
        ->type_name("FIRST:END");
    app.add_option("--shard", options->shard,
                   "The same as shard K (from 0) of N: N contiguous frame ranges, the first ones a frame "
                   "longer when N does not divide the path (what `sylva farm`'s array tasks pass)")
        ->type_name("K/N");
    app.add_flag("--list", options->list, "List the configurations and exit");
    app.add_flag("--save-frames", options->save_frames,
                 "Also write every configuration's frames as DIR/frames/<configuration>/frame_NNNN.png");
    app.footer(
        "Without --width/--height the bench renders at 480x270. Every configuration plays the same frames in "
        "this process, after one untimed warm-up frame; errors are means over the frames against the 3x3 "
        "supersampled full-geometry reference lit as the configuration is (normal or SH: each lighting family "
        "has its own reference, brute force, baseline sweep, Pareto fronts and verdict). Timings vary from run "
        "to run; errors do not, for any --threads.\n\n"
        "--representation, --sample-distance, --splats, --primitive-budget and --target-frame-ms add one "
        "configuration, measured beside the others: what `sylva play` draws with the same options (named as "
        "--list names it, e.g. points_lines_d2; it is added to --only). d' and the budgets apply to points_lines "
        "only; with another representation they are refused. --lighting lights every configuration that does "
        "not name its own lighting.");
    return [options] { return bench(*options); };
}

}  // namespace sylva
