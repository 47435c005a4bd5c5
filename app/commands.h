#pragma once
// The command line: each command registers its options on a CLI11 sub-command and returns the
// process exit code (0 ok, 1 runtime failure, 2 bad input).
#include <CLI/CLI.hpp>
#include <functional>

namespace sylva {

using command_runner = std::function<int()>;

command_runner add_play_command(CLI::App& app);
command_runner add_view_command(CLI::App& app);
command_runner add_plant_command(CLI::App& app);
command_runner add_export_cloud_command(CLI::App& app);
command_runner add_export_lodf_command(CLI::App& app);
command_runner add_lodf_bench_command(CLI::App& app);
command_runner add_lodf_quality_command(CLI::App& app);
command_runner add_inspect_command(CLI::App& app);
command_runner add_implicit_ao_command(CLI::App& app);
command_runner add_implicit_look_command(CLI::App& app);
command_runner add_bake_command(CLI::App& app);
command_runner add_stress_command(CLI::App& app);
command_runner add_bench_command(CLI::App& app);
command_runner add_calibrate_command(CLI::App& app);
command_runner add_merge_command(CLI::App& app);
command_runner add_farm_command(CLI::App& app);

constexpr int k_exit_ok = 0;
constexpr int k_exit_failure = 1;
constexpr int k_exit_bad_input = 2;

}  // namespace sylva
