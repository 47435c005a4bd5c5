#include "app/scenario_options.h"

#include <filesystem>
#include <string>
#include <tuple>
#include <spdlog/spdlog.h>

#include "scenarios/scenario_loader.h"

namespace sylva {

void add_scenario_options(CLI::App& command, scenario_options& options) {
    command.add_option(
        "scenario", options.path,
        "Scenario JSON file (format: docs/scenario_format.md), or the name of a bundled "
        "scenario (default, tiny, single_tree, forest, meadow, landscape, time_of_day, valley); default: "
        "the bundled default");
    command.add_option("--frames", options.frames, "Number of frames to play (overrides the scenario)")
        ->check(CLI::Range(1u, 1000000u));
    command.add_option("--width", options.width, "Image width in pixels (overrides the scenario)")
        ->check(CLI::Range(16u, 16384u));
    command.add_option("--height", options.height, "Image height in pixels (overrides the scenario)")
        ->check(CLI::Range(16u, 16384u));
    command.add_option("--threads", options.threads,
                       "Worker threads for the frame's systems (0: every hardware thread). Results "
                       "are bit-identical for any value")
        ->check(CLI::Range(0, 256));
    command
        .add_option("--representation", options.representation,
                    "How plants are drawn (overrides lod.representation): mesh_levels (full, reduced and "
                    "far meshes by distance), points_lines (Deussen 2002 points and lines), "
                    "billboard_clouds (Behrendt 2005: meshes near, billboard clouds beyond "
                    "lod.cloud_distance_m, crossed billboards far) or ladder (each species' ladder of "
                    "representations by projected size: lod.ladder, else the papers')")
        ->check(CLI::IsMember({"mesh_levels", "points_lines", "billboard_clouds", "ladder"}));
    command
        .add_option(
            "--lighting", options.lighting,
            "How every species is lit (overrides lod.lighting and each species' own): "
            "normal_mapped "
            "(by its normals), pre_lit (billboard clouds from the page lit at bake time), sh "
            "(precomputed radiance transfer with self-shadowing in every representation, Behrendt "
            "2005 §4; the first run bakes the transfer into the cache), implicit (Luft 2007: "
            "normals realigned to the foliage's implicit surface, ambient darkened by its density; "
            "baked into the model once, species.implicit tunes it) or sh_implicit (SH transfer baked from the "
            "realigned normals, the sky's light darkened by the density)")
        ->check(CLI::IsMember({"normal_mapped", "pre_lit", "sh", "implicit", "sh_implicit"}));
    command
        .add_option("--style", options.style,
                    "photo; toon: shading quantised into bands; lines: ink lines where the normal or depth "
                    "buffer jumps (Luft 2007 §4's non-photorealistic uses; with --lighting implicit both "
                    "follow the crown's shape; overrides render.style)")
        ->check(CLI::IsMember({"photo", "toon", "lines"}));
    command
        .add_option("--sample-distance", options.sample_distance_px,
                    "Deussen 2002 d' in pixels: the screen distance between point/line samples (overrides "
                    "lod.sample_distance_px; larger is faster and coarser)")
        ->check(CLI::Range(0.05f, 64.0f));
    command
        .add_option(
            "--splats", options.splats,
            "How point samples are drawn (overrides lod.splats): soft (Gaussian splats that "
            "each deposit the leaf area they stand for, over a visibility pass; smoother and "
            "steadier far foliage) or opaque (Deussen 2002's opaque squares)")
        ->check(CLI::IsMember({"soft", "opaque"}));
    command
        .add_option("--primitive-budget", options.primitive_budget,
                    "Adapt d' every frame to draw about this many triangle equivalents (points_lines; "
                    "Deussen 2002 §5.4; overrides lod.primitive_budget)")
        ->check(CLI::Range(0.0, 1e9));
    command
        .add_option("--target-frame-ms", options.target_frame_ms,
                    "Hold this GPU frame time (not deterministic; overrides lod.target_frame_ms): "
                    "with points_lines by adapting d' every frame, with --representation ladder by "
                    "adapting the auto ladder's plant budget every frame, from every plant on its "
                    "cheapest rung (--plant-budget-ms gives another start; the file's plant budget "
                    "is not one)")
        ->check(CLI::Range(0.0, 1e5));
    command
        .add_option("--plant-budget-ms", options.plant_budget_ms,
                    "With --representation ladder: choose every plant's rung each frame from tables measured per "
                    "species and rung (once, kept in the bake cache) so that the plants' predicted cost stays "
                    "within this many ms (the auto ladder; overrides lod.plant_budget_ms; 0: by projected size)")
        ->check(CLI::Range(0.0, 1e5));
    command
        .add_option("--max-error", options.max_error,
                    "With --representation ladder, instead of a budget: draw every plant on the cheapest rung whose "
                    "measured mean colour error per plant pixel (0..1) is at most this (overrides lod.max_error)")
        ->check(CLI::Range(0.0, 1.0));
    command
        .add_option(
            "--gain-per-ms", options.gain_per_ms,
            "With --representation ladder: buy a plant a dearer rung only where each ms of it puts "
            "right at least this much error (pixels' worth of colour error, from the same tables), "
            "in every frame alike: alone it spends what each frame is worth (the file's plant "
            "budget is dropped); with --plant-budget-ms or --target-frame-ms the budget also caps "
            "it (overrides lod.gain_per_ms; 0: none)")
        ->check(CLI::Range(0.0, 1e6));
}

scenario load_scenario_file_or_bundled(const std::string& path) {
    const bool bare_name = path.find('/') == std::string::npos && !path.ends_with(".json");
    if (bare_name && !std::filesystem::exists(path)) return load_bundled_scenario(path);
    return load_scenario_file(path);
}

scenario load_with_overrides(const scenario_options& options) {
    scenario s = options.path.empty() ? load_default_scenario() : load_scenario_file_or_bundled(options.path);
    if (options.frames) s.frames = *options.frames;
    if (options.width) s.width = *options.width;
    if (options.height) s.height = *options.height;
    // The file's plant budget or error threshold chooses its ladder's rungs: another
    // representation asked for on the command line leaves them (a budget asked for there too is
    // still refused below).
    if (options.representation) draw_by(s, *options.representation);
    if (options.lighting) {
        s.lod.lighting = *options.lighting;
        for (species_settings& species : s.species) species.lighting = "scenario";
    }
    if (options.style) s.render.style = *options.style;
    if (options.sample_distance_px) s.lod.sample_distance_px = *options.sample_distance_px;
    if (options.splats) s.lod.splats = *options.splats;
    if (options.primitive_budget) {
        s.lod.primitive_budget = *options.primitive_budget;
        s.lod.target_frame_ms = 0.0;
    }
    // A budget or a target on the command line replaces the file's threshold, and the reverse.
    if (options.target_frame_ms) {
        s.lod.target_frame_ms = *options.target_frame_ms;
        s.lod.primitive_budget = 0.0;
        s.lod.max_error = 0.0;
        // Nor is the file's plant budget a start for a target it was not chosen with: the budget
        // climbs from every plant on its cheapest rung (systems/adapt_plant_budget_system.h)
        // unless --plant-budget-ms gives one. `landscape`'s 350 ms started a 150 ms target
        // above it, and the frames swung from 313 ms (the cut plants still dissolving) to 75.
        s.lod.plant_budget_ms = 0.0;
    }
    if (options.plant_budget_ms) {
        s.lod.plant_budget_ms = *options.plant_budget_ms;
        s.lod.max_error = 0.0;
    }
    if (options.gain_per_ms) {
        s.lod.gain_per_ms = *options.gain_per_ms;
        s.lod.max_error = 0.0;
        // A gain asked for alone spends what each frame is worth: the file's budget would cap it
        // at one frame's, as a budget it was not chosen with (--plant-budget-ms beside it caps it).
        if (!options.plant_budget_ms) s.lod.plant_budget_ms = 0.0;
    }
    if (options.max_error) {
        s.lod.max_error = *options.max_error;
        s.lod.plant_budget_ms = s.lod.gain_per_ms = 0.0;
        if (s.lod.representation == "ladder") s.lod.target_frame_ms = 0.0;
        if (options.plant_budget_ms || options.gain_per_ms ||
            (options.target_frame_ms && s.lod.representation == "ladder"))
            throw scenario_error(
                s.source, "/lod/max_error", std::to_string(s.lod.max_error),
                "--max-error chooses the rungs without a budget or a gain: give it or "
                "--plant-budget-ms/--target-frame-ms/--gain-per-ms, not both");
    }
    for (const auto& [field, option, value] :
         {std::tuple{"plant_budget_ms", "--plant-budget-ms", s.lod.plant_budget_ms},
          std::tuple{"max_error", "--max-error", s.lod.max_error},
          std::tuple{"gain_per_ms", "--gain-per-ms", s.lod.gain_per_ms}})
        if (value > 0.0 && s.lod.representation != "ladder")
            throw scenario_error(s.source, std::string("/lod/") + field, std::to_string(value),
                                 std::string(option) + " chooses the rungs of a ladder, but the scenario draws " +
                                     s.lod.representation + ": add --representation ladder");
    return s;
}

std::optional<scenario> load_or_report(const scenario_options& options) {
    try {
        return load_with_overrides(options);
    } catch (const scenario_error& e) {
        spdlog::error("{}", e.what());
        return std::nullopt;
    }
}

}  // namespace sylva
