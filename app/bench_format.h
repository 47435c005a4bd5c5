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

// Per configuration: on the Pareto front of (median frame ms, error)?
std::vector<bool> front_flags(const bench_report& report, error_of error);
const bench_configuration* find_configuration(const bench_report& report, std::string_view name);
double entry_or_nan(const std::map<std::string, double>& values, const std::string& key);

}  // namespace sylva::bench_format
