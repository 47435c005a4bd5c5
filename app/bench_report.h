#pragma once
// What `sylva bench` measured, and its four outputs: bench.json, bench.csv, a plot of frame
// time against image error with the Pareto front marked (SVG), and a markdown summary.
//
// Every configuration plays the same frames of the scenario's camera path in one process, side
// by side, so their timing ratios hold on a noisy machine. Error figures are means over the
// frames against the supersampled full-geometry reference of the same frame (DESIGN.md §3);
// they do not depend on the thread count, timings do.
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace sylva {

// Image error of a configuration against the reference, averaged over its frames.
struct bench_error {
    double rmse = 0.0;           // RGB, 0..1
    double psnr_db = 0.0;        // of the mean squared error over all frames (inf when zero)
    double ssim = 1.0;           // mean SSIM on luminance, Gaussian window (Wang et al. 2004)
    double perceptual = 0.0;     // mean LDR-FLIP error, 0..1 (Andersson et al. 2020)
    double coverage_iou = 1.0;   // plant mask intersection over union, from the ID buffers
    double popping = 0.0;        // mean |E_t - E_(t-1)| of the error image E (8-bit luminance units)
    double lighting_jump = 0.0;  // mean colour jump at representation switches (8-bit units)
    std::uint64_t switches = 0;  // representation switches measured for lighting_jump
};

struct bench_configuration {
    std::string name;         // unique, e.g. "brute_force", "baseline", "mesh_lod", "lod_scale_0.5"
    std::string family;       // what the configuration varies: "brute_force", "baseline", ...
    std::string description;  // one line for the summary
    double quality = 0.0;     // the swept setting's value (0 when the family has no sweep)
    std::uint32_t frames = 0;
    double frame_ms_median = 0.0;  // over every timing round's frames
    double frame_ms_min = 0.0;
    double frame_ms_max = 0.0;
    std::vector<double> frame_ms_rounds;  // the median of each timing round, in round order
    // Median over the rounds of this configuration's round median over the baseline's of the
    // same round; NaN without a baseline configuration, or for one timed in fewer rounds than
    // the baseline (the reference; bench_runner.h: timing_rounds).
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
    double reference_frame_ms_median = 0.0;
    // Costs fixed for every point/line configuration (bench_settings::costs); empty when each
    // used the device's own (bench_configuration::primitive_costs).
    std::map<std::string, double> primitive_costs;
    std::vector<bench_configuration> configurations;
    // Stopped early (bench_settings::stop, an interrupt): configurations may be missing or have
    // fewer frames than `frames`.
    bool partial = false;
};

// Indices of the configurations on the Pareto front of (median frame ms, error), both
// minimised: no other configuration is at least as good in both and better in one. Sorted by
// frame time. Of equal points only the first by index is kept; points with a NaN are left out.
std::vector<std::size_t> pareto_front(const std::vector<double>& frame_ms, const std::vector<double>& error);

// Each writes atomically (temporary file, then rename) and throws naming the path on failure.
// Numbers keep six significant digits (whole numbers from 1e6 up). JSON has no infinity: an
// infinite value (PSNR of the reference against itself) is written as the string "inf" ("-inf"),
// NaN as null. The CSV writes inf as inf and leaves NaN or absent values empty. Each
// configuration's "on_pareto_front" is for (median frame ms, perceptual error).
void write_bench_json(const std::filesystem::path& path, const bench_report& report);
void write_bench_csv(const std::filesystem::path& path, const bench_report& report);
void write_bench_plot_svg(const std::filesystem::path& path, const bench_report& report);
void write_bench_summary_md(const std::filesystem::path& path, const bench_report& report);

}  // namespace sylva
