// sylva: real-time rendering of plant ecosystems. See README.md, or `sylva --help`.
#include <malloc.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "app/run_options.h"
#include "io/input_file.h"
#include "scenarios/scenario_loader.h"

namespace {

int run(int argc, char** argv);

}  // namespace

// Whatever escapes a command ends the process with one line naming it, never an abort: exit 2
// when it is about the input (a scenario or another file the user gave), 1 otherwise.
int main(int argc, char** argv) {
    // glibc returns freed memory at the top of the heap to the system once 128 KiB of it is
    // free (more once a large free raises that), and the next frame faults the pages in again,
    // a cost the process's CPU time counts. Until the frames before have raised the threshold,
    // llvmpipe's per-frame memory is trimmed every frame: shader work calibrated first in a
    // process timed 0.4 px triangles at 85-92 ms a frame (+-2-19) where they take 17-18
    // (+-0.3) with the memory kept, and refused the fit in some runs (the marginal time of small
    // triangles below zero); steady play is unchanged (default 230-236 ms a frame either way).
    // At most 256 MiB of freed memory stays mapped.
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    try {
        return run(argc, argv);
    } catch (const sylva::scenario_error& e) {
        spdlog::error("{}", e.what());
        return sylva::k_exit_bad_input;
    } catch (const sylva::input_error& e) {
        spdlog::error("{}", e.what());
        return sylva::k_exit_bad_input;
    } catch (const std::bad_alloc&) {
        spdlog::error("out of memory");
        return sylva::k_exit_failure;
    } catch (const std::exception& e) {
        spdlog::error("{}", e.what());
        return sylva::k_exit_failure;
    } catch (...) {
        spdlog::error("an unknown error ended the program");
        return sylva::k_exit_failure;
    }
}

namespace {

int run(int argc, char** argv) {
    spdlog::set_pattern("[sylva] %v");
    CLI::App app{
        "Sylva renders landscapes with hundreds of thousands of plants in real time and measures\n"
        "what each millisecond buys. Run `sylva COMMAND --help` for a command's options."};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "Every command's options");
    std::vector<std::pair<CLI::App*, sylva::command_runner>> commands;
    auto* play = app.add_subcommand("play", "Play a scenario headless: frames (PNG) and metrics.json");
    commands.emplace_back(play, sylva::add_play_command(*play));
    auto* view = app.add_subcommand("view", "Open a window and walk through a scenario");
    commands.emplace_back(view, sylva::add_view_command(*view));
    auto* plant = app.add_subcommand(
        "plant", "Generate a species preset and export it as binary glTF (.glb)");
    commands.emplace_back(plant, sylva::add_plant_command(*plant));
    auto* export_cloud = app.add_subcommand(
        "export-cloud", "Bake a plant's billboard cloud (Behrendt 2005) and export it as binary glTF (.glb)");
    commands.emplace_back(export_cloud, sylva::add_export_cloud_command(*export_cloud));
    auto* export_lodf = app.add_subcommand(
        "export-lodf", "Bake a plant's LoDF (Rebollo 2006) and export it at any leaf count as binary glTF (.glb)");
    commands.emplace_back(export_lodf, sylva::add_export_lodf_command(*export_lodf));
    auto* lodf_bench = app.add_subcommand(
        "lodf-bench", "Traverse a plant's LoDF levels (Rebollo 2006 §5): bytes and time per change against re-extraction");
    commands.emplace_back(lodf_bench, sylva::add_lodf_bench_command(*lodf_bench));
    auto* lodf_quality = app.add_subcommand(
        "lodf-quality", "LoDF's image quality at equal leaf count against leaf shrink and the mesh levels (FLIP, SSIM, IoU)");
    commands.emplace_back(lodf_quality, sylva::add_lodf_quality_command(*lodf_quality));
    auto* implicit_ao = app.add_subcommand(
        "implicit-ao", "Rank correlation of Luft 2007's ambient coefficient with ray-cast occlusion, per vertex");
    commands.emplace_back(implicit_ao, sylva::add_implicit_ao_command(*implicit_ao));
    auto* implicit_look = app.add_subcommand(
        "implicit-look", "Crown noise (variance of a Laplacian) and brightness, lit by Luft 2007's implicit surface "
                         "against the species' normals");
    commands.emplace_back(implicit_look, sylva::add_implicit_look_command(*implicit_look));
    auto* inspect = app.add_subcommand(
        "inspect", "Print a plant's triangles, leaves, branches, materials, bounds, units and LoDF structure");
    commands.emplace_back(inspect, sylva::add_inspect_command(*inspect));
    auto* bake = app.add_subcommand(
        "bake",
        "Make what a scenario plays with (its species' bakes, its ladder's rung tables, the "
        "device's costs), or one glTF model's bakes, in the bake cache");
    commands.emplace_back(bake, sylva::add_bake_command(*bake));
    auto* bench = app.add_subcommand(
        "bench", "Measure frame time against image error for every configuration; writes a table and a plot");
    commands.emplace_back(bench, sylva::add_bench_command(*bench));
    auto* calibrate = app.add_subcommand(
        "calibrate", "Measure what a triangle, a point and a line cost on this GL device, and cache it");
    commands.emplace_back(calibrate, sylva::add_calibrate_command(*calibrate));
    auto* merge = app.add_subcommand(
        "merge", "Join the outputs of shards of one run (--frame-range) into what the whole run writes");
    commands.emplace_back(merge, sylva::add_merge_command(*merge));
    auto* farm = app.add_subcommand(
        "farm", "Run a play or bench as a Slurm array job of frame shards, merged when all succeeded");
    commands.emplace_back(farm, sylva::add_farm_command(*farm));
    auto* stress = app.add_subcommand("stress", "Run the numerical stress suite and print a table of its checks");
    commands.emplace_back(stress, sylva::add_stress_command(*stress));
    try {
        app.parse(argc, argv);
        sylva::remember_run_options(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : sylva::k_exit_bad_input;
    }
    for (auto& [command, run_command] : commands)
        if (command->parsed()) return run_command();
    return sylva::k_exit_bad_input;
}

}  // namespace
