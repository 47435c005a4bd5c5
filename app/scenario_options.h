#pragma once
// Options every command that plays a scenario shares: which scenario, and the overrides of its
// frame count, resolution and thread count.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "scenarios/scenario.h"

namespace sylva {

struct scenario_options {
    std::string path;  // empty: the embedded default scenario
    std::optional<std::uint32_t> frames;
    std::optional<std::uint32_t> width;
    std::optional<std::uint32_t> height;
    int threads = 0;
    // Overrides of the scenario's `lod` section (scenarios/scenario.h).
    std::optional<std::string> representation;
    std::optional<std::string> lighting;
    std::optional<std::string> style;
    std::optional<float> sample_distance_px;
    std::optional<std::string> splats;
    std::optional<double> primitive_budget;
    std::optional<double> target_frame_ms;
    std::optional<double> plant_budget_ms;
    std::optional<double> max_error;
    std::optional<double> gain_per_ms;
};

void add_scenario_options(CLI::App& command, scenario_options& options);
// Loads the scenario (or the default) and applies the overrides; throws scenario_error.
scenario load_with_overrides(const scenario_options& options);
// The same, but reports a scenario error (file, JSON path, value) and returns nothing, so the
// command can exit with k_exit_bad_input before it writes anything.
// A path that names no file and looks like a bare name ("forest") means a bundled scenario.
scenario load_scenario_file_or_bundled(const std::string& path);

std::optional<scenario> load_or_report(const scenario_options& options);

}  // namespace sylva
