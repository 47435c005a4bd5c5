// `sylva bake SCENARIO.json|MODEL.glb`: builds every species model a scenario needs (or one
// imported glTF model) and its representations (crossed billboard, Deussen 2002 points and
// lines, Behrendt 2005 billboard cloud) into the bake cache, with a progress bar; then, for a
// scenario, whatever else its play makes on a GL device (an auto ladder's rungs and measured
// tables, the device's primitive costs, shells, LoDF) by building the player `sylva play`
// builds, on a headless context. Later plays and benches then start at once.
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "app/commands.h"
#include "app/rung_table_report.h"
#include "app/scenario_options.h"
#include "app/scenario_player.h"
#include "io/input_file.h"
#include "models/cache/bake_cache.h"
#include "models/cache/plant_model_io.h"
#include "scenarios/scenario_loader.h"
#include "setup/species_models.h"
#include "systems/render/gl_context.h"

namespace sylva {
namespace {

struct bake_options {
    std::string input;
    std::string cache_dir;
    bool force = false;
    bool species_only = false;
    bool print_tables = false;
};

// One line, redrawn in place: [#####-----] 3/7 oak (baked, 412 ms)
void progress(std::size_t done, std::size_t total, const std::string& what) {
    constexpr int k_width = 24;
    const int filled = total ? int(double(done) / double(total) * k_width) : k_width;
    std::string bar(std::size_t(filled), '#');
    bar.append(std::size_t(k_width - filled), '-');
    std::fprintf(stderr, "\r[sylva] baking [%s] %zu/%zu %-40s", bar.c_str(), done, total, what.c_str());
    if (done == total) std::fprintf(stderr, "\n");
}

std::vector<species_settings> species_to_bake(const bake_options& o, std::uint64_t& seed,
                                              std::optional<scenario>& loaded) {
    const std::filesystem::path input(o.input);
    const std::string ext = input.extension().string();
    if (ext == ".gltf" || ext == ".glb") {
        if (!std::filesystem::exists(input)) throw scenario_error(o.input, "", "", "file not found");
        species_settings model;
        model.name = input.stem().string();
        model.model = std::filesystem::absolute(input).string();
        return {model};
    }
    const scenario& s = loaded.emplace(load_scenario_file_or_bundled(o.input));
    seed = s.seed;
    // As spawning resolves them, so play finds these entries (an "implicit" model is its own).
    std::vector<species_settings> out;
    for (const species_settings& species : s.species) out.push_back(resolved_species(s, species));
    return out;
}

// What playing `s` makes beyond its species' bakes, made as `sylva play` makes it: the player
// is built on a headless context at the scenario's size, through `cache`, and dropped.
int bake_what_play_makes(const scenario& s, bake_cache& cache, bool print_tables) {
    const std::size_t hits = cache.hits(), misses = cache.misses();
    const auto start = std::chrono::steady_clock::now();
    try {
        render::context_options context_options;
        context_options.width = int(s.width);
        context_options.height = int(s.height);
        context_options.headless = true;
        auto context = render::create_context(context_options);
        spdlog::info("making what playing '{}' ({} representation) needs on {}", s.name,
                     s.lod.representation, context->renderer());
        const scenario_player player(s, 0, context.get(), &cache);
        if (print_tables) {
            std::vector<std::string> names;
            for (const species_settings& species : s.species) names.push_back(species.name);
            std::fputs(rung_table_report(s.name, names, player.ladder_budget()).c_str(), stdout);
        }
    } catch (const std::exception& e) {
        spdlog::error("{}; the species above are baked, the rest is made at the first play",
                      e.what());
        return k_exit_failure;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    spdlog::info(
        "what '{}' plays with on this device (its ladder's rungs and tables, primitive "
        "costs, ...): {} cache entries reused, {} made, in {:.1f} s",
        s.name, cache.hits() - hits, cache.misses() - misses, seconds);
    return k_exit_ok;
}

int bake(const bake_options& o) {
    std::uint64_t seed = 1;
    std::vector<species_settings> species;
    std::optional<scenario> loaded;  // when the input is a scenario
    try {
        species = species_to_bake(o, seed, loaded);
    } catch (const scenario_error& e) {
        spdlog::error("{}", e.what());
        return k_exit_bad_input;
    }
    if (o.print_tables && !loaded) {
        spdlog::error("{}: --print-tables prints a scenario's rung tables; a model has none",
                      o.input);
        return k_exit_bad_input;
    }
    bake_cache cache(o.cache_dir);
    if (o.force) cache.rebake_all();
    try {
        for (std::size_t i = 0; i < species.size(); ++i) {
            // The same seed derivation as scenario spawning, so play finds these entries.
            const std::uint64_t species_seed = species_seed_of(seed, i);
            const std::uint64_t key = species_model_key(species[i], species_seed);
            const std::filesystem::path billboard =
                cache.path_of("billboards", species_billboard_key(species[i], species_seed));
            const std::filesystem::path point_lines =
                cache.path_of("point_lines", species_point_line_key(species[i], species_seed));
            const std::filesystem::path cloud =
                cache.path_of("billboard_clouds", species_billboard_cloud_key(species[i], species_seed));
            const bool cached = !o.force && std::filesystem::exists(cache.path_of("plants", key)) &&
                                std::filesystem::exists(billboard) &&
                                std::filesystem::exists(point_lines) &&
                                std::filesystem::exists(cloud);
            progress(i, species.size(), species[i].name + (cached ? " (cached)" : " (baking)"));
            const auto start = std::chrono::steady_clock::now();
            const plant_model model = load_species_model(species[i], species_seed, &cache);
            load_species_billboard(species[i], species_seed, model, &cache);     // the crossed billboard
            load_species_point_lines(species[i], species_seed, model, &cache);  // points and lines
            load_species_billboard_cloud(species[i], species_seed, model, &cache);
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            progress(i + 1, species.size(), species[i].name + (cached ? " (cached)" : " (baked, " + std::to_string(int(ms)) + " ms)"));
        }
    } catch (const input_error& e) {  // a model file that cannot be used: bad input
        std::fprintf(stderr, "\n");
        spdlog::error("{}", e.what());
        return k_exit_bad_input;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "\n");
        spdlog::error("{}", e.what());
        return k_exit_failure;
    }
    spdlog::info("{} species (model, crossed billboard, points and lines, billboard cloud each): {} cache entries reused, {} baked, "
                 "in {}",
                 species.size(), cache.hits(), cache.misses(), cache.root().string());
    if (!loaded || o.species_only) return k_exit_ok;
    return bake_what_play_makes(*loaded, cache, o.print_tables);
}

}  // namespace

command_runner add_bake_command(CLI::App& app) {
    auto options = std::make_shared<bake_options>();
    app.add_option("input", options->input, "A scenario (.json) or a plant model (.gltf, .glb)")->required();
    app.add_option("--cache", options->cache_dir,
                   "Cache folder (default: $SYLVA_CACHE_DIR, else $XDG_CACHE_HOME/sylva, else ~/.cache/sylva)");
    app.add_flag("--force", options->force,
                 "Bake and measure everything again even when the cache has an entry");
    CLI::Option* species_only =
        app.add_flag("--species-only", options->species_only,
                     "Only the species' models and representations: not what a scenario's play "
                     "measures on the GL device (an auto ladder's rung tables, the device's "
                     "primitive costs)");
    app.add_flag("--print-tables", options->print_tables,
                 "Print what the auto ladder chooses from: each species' rungs' error per plant "
                 "pixel and view and shadow cost (us, this device's) at every projected size")
        ->excludes(species_only);
    return [options] { return bake(*options); };
}

}  // namespace sylva
