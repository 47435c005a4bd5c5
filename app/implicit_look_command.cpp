// `sylva implicit-look SCENARIO... [--frames N] [--width W] [--height H] [--json FILE]`: what Luft
// 2007's implicit-surface illumination does to a crown's look (issue 22, "less noise, same
// shape"). Each scenario is played twice, its species lit by their own normals and then by the
// implicit surface (realigned normals, density ambient), with the same camera and the same
// ladder, by projected size (an auto ladder's solver would choose each lighting's rungs from its
// own tables); in every frame the crown mask is the plants' pixels (ID buffer) whose 5x5
// neighbourhood is all plant in both frames, so silhouettes never count. Reported over all
// frames' crown pixels: the variance of a Laplacian of luma (the high frequencies the leaves'
// random orientations put there) and the mean luma (the crown's brightness, which the density
// ambient lowers).
#include <spdlog/spdlog.h>

#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/scenario_options.h"
#include "app/scenario_player.h"
#include "io/atomic_file.h"
#include "measure/crown_texture.h"
#include "models/cache/bake_cache.h"
#include "scenarios/scenario_loader.h"
#include "systems/render/gl_context.h"

namespace sylva {
namespace {

struct implicit_look_options {
    std::vector<std::string> scenarios;
    std::uint32_t frames = 12;
    std::uint32_t width = 480;
    std::uint32_t height = 270;
    std::string json;
};

// The frame a player just drew: its image, and 1 where the ID buffer holds a plant.
struct frame_look {
    image_rgba8 image;
    std::vector<std::uint8_t> plants;
};

frame_look step(scenario_player& player) {
    (void)player.step();
    frame_look look{player.capture(), {}};
    const std::vector<std::uint32_t> ids = player.capture_plant_ids();
    look.plants.resize(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) look.plants[i] = ids[i] != 0 ? 1 : 0;
    return look;
}

player_options lit(const std::string& lighting) {
    player_options options;
    options.lighting = lighting;
    options.id_buffer = true;
    return options;
}

struct look_result {
    std::string scenario;
    std::uint32_t frames = 0;
    crown_texture normal, implicit;
};

// Both lightings played frame by frame side by side (each player draws into its own targets),
// so a walk of any length holds two frames at a time.
look_result measure(const scenario& s, render::gl_context& context, bake_cache& cache) {
    look_result r;
    r.scenario = s.name;
    r.frames = s.frames;
    spdlog::info("{}: {} frames, lit by the species' normals and by the implicit surface (Luft 2007)", s.name,
                 s.frames);
    scenario_player normal_player(s, 0, &context, &cache, lit("normal_mapped"));
    scenario_player implicit_player(s, 0, &context, &cache, lit("implicit"));
    for (std::uint32_t f = 0; f < s.frames; ++f) {
        const frame_look normal = step(normal_player);
        const frame_look implicit = step(implicit_player);
        std::vector<std::uint8_t> both(normal.plants.size());
        for (std::size_t i = 0; i < both.size(); ++i) both[i] = normal.plants[i] & implicit.plants[i];
        const std::vector<std::uint8_t> crown = mask_interior(both, s.width, s.height, 2);
        r.normal = pooled(r.normal, crown_texture_of(normal.image, crown));
        r.implicit = pooled(r.implicit, crown_texture_of(implicit.image, crown));
    }
    return r;
}

int implicit_look(const implicit_look_options& o) {
    std::vector<scenario> scenarios;
    for (const std::string& name : o.scenarios) {
        try {
            scenario s = load_scenario_file_or_bundled(name);
            s.frames = o.frames;
            s.width = o.width;
            s.height = o.height;
            // The same ladder means the same rungs: under `auto` each lighting's solver chooses from
            // its own rung tables (default's budget put 681 plants on clouds implicit-lit and 379
            // normal-lit in the first frame), so the look would compare representations as well
            // as lightings. Its ladder is played by projected size (the sizes in the file) instead.
            if (s.lod.plant_budget_ms > 0.0 || s.lod.max_error > 0.0 ||
                s.lod.target_frame_ms > 0.0 || s.lod.gain_per_ms > 0.0) {
                spdlog::info("implicit-look: {} chooses its rungs under a budget; both lightings play its ladder by "
                             "projected size, so every plant is on the same rung in both",
                             s.name);
                s.lod.plant_budget_ms = s.lod.max_error = s.lod.target_frame_ms =
                    s.lod.gain_per_ms = 0.0;
            }
            scenarios.push_back(std::move(s));
        } catch (const scenario_error& e) {
            spdlog::error("implicit-look: {}", e.what());
            return k_exit_bad_input;
        }
    }
    render::context_options context_options;
    context_options.width = int(o.width);
    context_options.height = int(o.height);
    context_options.headless = true;
    std::unique_ptr<render::gl_context> context;
    try {
        context = render::create_context(context_options);
    } catch (const std::exception& e) {
        spdlog::error("implicit-look: no GL context: {}", e.what());
        return k_exit_failure;
    }
    bake_cache cache;
    std::vector<look_result> results;
    for (const scenario& s : scenarios) {
        try {
            results.push_back(measure(s, *context, cache));
        } catch (const std::exception& e) {
            spdlog::error("implicit-look: {}: {}", s.name, e.what());
            return k_exit_failure;
        }
    }
    std::printf("%-12s %6s %9s | %12s %12s %9s | %9s %9s %9s\n", "scenario", "frames", "crown px", "Lap. var normal",
                "implicit", "change", "luma norm", "implicit", "change");
    nlohmann::ordered_json json = nlohmann::ordered_json::array();
    for (const look_result& r : results) {
        const auto change = [](double to, double from) { return from > 0.0 ? 100.0 * (to / from - 1.0) : 0.0; };
        const double energy = change(r.implicit.laplacian_variance, r.normal.laplacian_variance);
        const double luma = change(r.implicit.mean_luma, r.normal.mean_luma);
        if (r.normal.pixels == 0) {
            std::printf("%-12s %6u %9s | no crown pixels (no plant covers a 5x5 block): n/a\n", r.scenario.c_str(),
                        r.frames, "0");
        } else {
            std::printf("%-12s %6u %9zu | %15.1f %12.1f %8.1f%% | %9.1f %9.1f %8.1f%%\n", r.scenario.c_str(), r.frames,
                        r.normal.pixels, r.normal.laplacian_variance, r.implicit.laplacian_variance, energy,
                        r.normal.mean_luma, r.implicit.mean_luma, luma);
        }
        nlohmann::ordered_json row{{"scenario", r.scenario}, {"frames", r.frames}, {"crown_pixels", r.normal.pixels}};
        if (r.normal.pixels > 0) {
            row["laplacian_variance_normal"] = r.normal.laplacian_variance;
            row["laplacian_variance_implicit"] = r.implicit.laplacian_variance;
            row["laplacian_variance_change_percent"] = energy;
            row["mean_luma_normal"] = r.normal.mean_luma;
            row["mean_luma_implicit"] = r.implicit.mean_luma;
            row["mean_luma_change_percent"] = luma;
        }
        json.push_back(row);
    }
    if (!o.json.empty()) write_atomically(o.json, json.dump(2) + "\n");
    return k_exit_ok;
}

}  // namespace

command_runner add_implicit_look_command(CLI::App& app) {
    auto options = std::make_shared<implicit_look_options>();
    app.add_option("scenarios", options->scenarios, "Scenario files, or bundled scenario names (default, forest, ...)")
        ->required();
    app.add_option("--frames", options->frames, "Frames of each scenario's walk, from its start")
        ->check(CLI::Range(1u, 10000u))
        ->capture_default_str();
    app.add_option("--width", options->width, "Frame width in pixels")->check(CLI::Range(16u, 8192u))->capture_default_str();
    app.add_option("--height", options->height, "Frame height in pixels")
        ->check(CLI::Range(16u, 8192u))
        ->capture_default_str();
    app.add_option("--json", options->json, "Also write the table as JSON to this file");
    return [options] { return implicit_look(*options); };
}

}  // namespace sylva
