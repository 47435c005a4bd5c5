#pragma once
// Shared by the writers of `sylva bench`'s outputs (app/bench_report.cpp: JSON, CSV, summary;
// app/bench_plot.cpp: the SVG plot): locale-independent number formatting, atomic file writes
// and the Pareto flags of a report. Files are written with io/atomic_file.h.
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "app/bench_report.h"

namespace sylva::bench_format {

// The error a plot panel or a Pareto front is taken over.
using error_of = double (*)(const bench_configuration&);
double flip_error(const bench_configuration& c);  // FLIP (perceptual)
double ssim_error(const bench_configuration& c);  // 1 - SSIM

// Six significant digits, never coarser than a whole number (byte and triangle counts stay exact).
double rounded(double v);
// Shortest fixed notation that reads back as v: "2000000", "0.02", never an exponent.
std::string plain(double v);
std::string fixed(double v, int decimals);
std::string significant(double v, int digits);

// Per configuration: on the Pareto front of (median frame ms, error) of its lighting family?
// (Errors against different references are never compared.)
std::vector<bool> front_flags(const bench_report& report, error_of error);
const bench_configuration* find_configuration(const bench_report& report, std::string_view name);
// Indices of the configurations of one lighting family, in report order.
std::vector<std::size_t> in_lighting_family(const bench_report& report, std::string_view lighting);
// A lighting family's brute force (the first of family brute_force) and baseline (the first of
// family baseline at k_named_baseline_distance_m), or null.
const bench_configuration* family_brute_force(const bench_report& report, std::string_view lighting);
const bench_configuration* family_baseline(const bench_report& report, std::string_view lighting);
// a's frame time over b's: the median of the round-by-round ratios when both were timed in the
// same rounds (bench_runner.h: timing_rounds), else the ratio of their medians.
double time_ratio(const bench_configuration& a, const bench_configuration& b);
double entry_or_nan(const std::map<std::string, double>& values, const std::string& key);

}  // namespace sylva::bench_format
