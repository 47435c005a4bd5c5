#pragma once
// What `sylva bench` measured, and its four outputs: bench.json, bench.csv, a plot of frame
// time against image error with the Pareto front marked (SVG), and a markdown summary.
//
// Every configuration plays the same frames of the scenario's camera path in one process, side
// by side, so their timing ratios hold on a noisy machine. Error figures are means over the
// frames against the supersampled full-geometry reference of the same frame, lit as the
// configuration is (DESIGN.md §3); they do not depend on the thread count, timings do.
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace sylva {

// Image error of a configuration against its lighting family's reference, averaged over its
// frames.
struct bench_error {
    double rmse = 0.0;           // RGB, 0..1
    double psnr_db = 0.0;        // of the mean squared error over all frames (inf when zero)
    double ssim = 1.0;           // mean SSIM on luminance, Gaussian window (Wang et al. 2004)
    double perceptual = 0.0;     // mean LDR-FLIP error, 0..1 (Andersson et al. 2020)
    double coverage_iou = 1.0;   // plant mask intersection over union, from the ID buffers
    double popping = 0.0;        // mean |E_t - E_(t-1)| of the error image E (8-bit luminance units)
    // Mean colour jump over whole transitions between representations, beyond the reference's
    // change over the same frames (8-bit units; measure/transition_windows.h). NaN when the
    // configuration made no transition the metric could measure: "n/a", never a flattering 0.
    double lighting_jump = std::numeric_limits<double>::quiet_NaN();
    // Transitions along the path: measured (lighting_jump is their mean), by kind (fade,
    // switch, blend, eco_tile_set); complete but covering too few pixels to measure; cut off by
    // the path's first or last frame.
    std::uint64_t transitions = 0;
    std::map<std::string, std::uint64_t> transitions_by_kind;
    std::uint64_t transition_frames = 0;  // frames the measured transitions span, summed
    std::uint64_t transitions_too_small = 0;
    std::uint64_t transitions_cut_off = 0;
};

// One frame of a configuration as measured: what a sharded bench's figures are recomputed from
// (`sylva merge`, app/shard_merge.h), so a merged report is the whole bench's.
struct bench_frame {
    std::uint32_t frame = 0;
    std::vector<double> frame_ms;  // one per timing round, round 0 first
    double rmse = 0.0;             // of this frame against its reference
    double ssim = 0.0;
    double perceptual = 0.0;
    double coverage_iou = 0.0;
    double popping = std::numeric_limits<double>::quiet_NaN();  // NaN at the path's frame 0
    double upload_bytes = 0.0;
    std::map<std::string, double> cpu_ms, gpu_ms, primitives;  // as bench_configuration keys them
};

// One complete transition window (measure/transition_windows.h), kept by the run (or shard)
// that played the frame that showed its end: the first unchanged frame after it, to_frame + 1.
struct bench_transition {
    std::uint32_t first_plant = 0;
    std::uint32_t plant_count = 1;
    std::uint32_t from_frame = 0;
    std::uint32_t to_frame = 0;
    std::string kind;  // transition_kind()
    double jump = std::numeric_limits<double>::quiet_NaN();  // NaN: too few pixels to measure
};

struct bench_configuration {
    std::string name;         // unique, e.g. "brute_force", "baseline", "mesh_lod", "lod_scale_0.5"
    std::string family;       // what the configuration varies: "brute_force", "baseline", ...
    // Its lighting family (bench_lighting_family::name): the reference its errors are against.
    std::string lighting;
    std::string description;  // one line for the summary
    double quality = 0.0;     // the swept setting's value (0 when the family has no sweep)
    std::uint32_t frames = 0;
    double frame_ms_median = 0.0;  // over every timing round's frames
    double frame_ms_min = 0.0;
    double frame_ms_max = 0.0;
    std::vector<double> frame_ms_rounds;  // the median of each timing round, in round order
    // Median over the rounds of this configuration's round median over its lighting family's
    // baseline's of the same round; NaN without a baseline there, or for one timed in fewer
    // rounds than the baseline (the reference; bench_runner.h: timing_rounds).
    double frame_ms_vs_baseline = std::numeric_limits<double>::quiet_NaN();
    std::map<std::string, double> cpu_ms;       // median per system, plus "total"
    std::map<std::string, double> gpu_ms;       // median per pass, plus "total"
    std::map<std::string, double> primitives;   // median per frame: triangles, points, lines,
                                                // shadow_triangles, and instances per representation
    double upload_bytes = 0.0;                  // median per frame
    double peak_memory_mb = 0.0;                // resident high-water mark while it ran
    // The device's relative primitive costs a point/line configuration selected with (triangle,
    // point, line; systems/render/primitive_cost_calibration.h), for its own d'; empty otherwise.
    std::map<std::string, double> primitive_costs;
    bench_error error;
    // What the figures above come from (summarize_records): every frame, every complete
    // transition whose end was seen in the frames played (to_frame + 1 among them), and the
    // windows the path cut off (began before frame 0, seen to end in the frames played; or
    // still open at the path's end).
    std::vector<bench_frame> frame_records;
    std::vector<bench_transition> transition_records;
    std::uint64_t transitions_cut_off = 0;
    // scenario_player::selection_inputs_hash of its player: shards must select alike to merge.
    std::uint64_t selection_inputs_hash = 0;
    // Merged from shards timed on several hosts: the time ratio to the baseline per host, from
    // that host's frames alone (frame_ms_vs_baseline is then NaN: no ratio across machines).
    std::map<std::string, double> frame_ms_vs_baseline_by_host;
};

// Configurations are compared only with others measured against the same reference: one lit as
// they are. Each lighting family has its reference, and within it its own brute force, baseline
// sweep, Pareto fronts and verdict.
struct bench_lighting_family {
    std::string name;         // "normal" (normal-mapped and pre-lit), "sh", or "scenario" (mixed)
    std::string description;  // what its reference is lit by
    double reference_frame_ms_median = 0.0;
    std::vector<double> reference_frame_ms;  // per frame played
};

// A shard of a bench (`--frame-range`), or one of the shards a merged report joins.
struct bench_shard {
    std::uint32_t first = 0;  // frames [first, end) of the path
    std::uint32_t end = 0;
    std::string host;
    std::string machine;
    int threads = 0;
    double replay_ms = 0.0;  // reaching the first frame, over every player of the shard
};

struct bench_report {
    std::string scenario;
    std::string source;
    std::string machine;
    std::string gl_renderer;
    int threads = 0;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::uint32_t frames = 0;
    std::uint32_t timing_rounds = 1;
    std::uint32_t reference_samples_per_pixel = 9;
    std::vector<bench_lighting_family> lighting_families;  // in order of first use
    // Costs fixed for every point/line configuration (bench_settings::costs); empty when each
    // used the device's own (bench_configuration::primitive_costs).
    std::map<std::string, double> primitive_costs;
    std::vector<bench_configuration> configurations;
    // Stopped early (bench_settings::stop, an interrupt): configurations may be missing or have
    // fewer frames than `frames`.
    bool partial = false;
    // The frames of the path this report holds: [0, frames) for a whole bench; a shard's own.
    bench_shard range;
    std::uint32_t path_frames = 0;
    std::vector<bench_shard> shards;  // a merged report's shards, in frame order; empty otherwise
    std::vector<std::string> options;  // the command's options but a shard's own (app/run_options.h)
};

// Reads what write_bench_json wrote, with its records (sylva merge). Throws std::runtime_error
// naming the path and the field.
bench_report read_bench_json(const std::filesystem::path& path);

// Indices of the configurations on the Pareto front of (median frame ms, error), both
// minimised: no other configuration is at least as good in both and better in one. Sorted by
// frame time. Of equal points only the first by index is kept; points with a NaN are left out.
std::vector<std::size_t> pareto_front(const std::vector<double>& frame_ms, const std::vector<double>& error);

// Each writes atomically (temporary file, then rename) and throws naming the path on failure.
// Numbers keep six significant digits (whole numbers from 1e6 up). JSON has no infinity: an
// infinite value (PSNR of the reference against itself) is written as the string "inf" ("-inf"),
// a value not measured (NaN) as null. The CSV writes inf as inf and "n/a" for what was not
// measured. Each configuration's "on_pareto_front" is for (median frame ms, perceptual error)
// within its lighting family. The summary and the plot treat each lighting family apart.
void write_bench_json(const std::filesystem::path& path, const bench_report& report);
void write_bench_csv(const std::filesystem::path& path, const bench_report& report);
void write_bench_plot_svg(const std::filesystem::path& path, const bench_report& report);
void write_bench_summary_md(const std::filesystem::path& path, const bench_report& report);

}  // namespace sylva
