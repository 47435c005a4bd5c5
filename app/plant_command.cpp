// `sylva plant`: generates a species preset and writes one level of it as binary glTF.
#include <spdlog/spdlog.h>

#include <string>

#include "app/commands.h"
#include "models/bake/implicit_illumination.h"
#include "models/gltf/gltf_export.h"
#include "models/generate/plant_library.h"

namespace sylva {
namespace {

struct plant_options {
    std::string species;
    std::uint64_t seed = 1;
    std::string lod = "full";
    std::string out;
    std::uint32_t texture_size = 512;
    bool implicit = false;
    bool list = false;
};

std::string preset_list() {
    std::string names;
    for (const std::string_view name : k_plant_presets)
        names += (names.empty() ? "" : ", ") + std::string(name);
    return names;
}

bool known_preset(const std::string& species) {
    for (const std::string_view name : k_plant_presets)
        if (name == species) return true;
    return false;
}

int plant(const plant_options& o) {
    if (o.list) {
        for (const std::string_view name : k_plant_presets)
            std::printf("%.*s\n", int(name.size()), name.data());
        return k_exit_ok;
    }
    if (o.species.empty() || o.out.empty()) {
        spdlog::error("plant: give a SPECIES and --out FILE.glb (or --list); species: {}",
                      preset_list());
        return k_exit_bad_input;
    }
    if (!known_preset(o.species)) {
        spdlog::error("plant: unknown species '{}'; the presets are {}", o.species, preset_list());
        return k_exit_bad_input;
    }
    const plant_lod lod = o.lod == "reduced" ? plant_lod::reduced
                          : o.lod == "far"   ? plant_lod::far
                                             : plant_lod::full;
    try {
        plant_model model = generate_plant_model(o.species, o.seed, o.texture_size);
        if (o.implicit) {
            implicit_settings settings;
            settings.seed = o.seed;
            const implicit_report report = bake_implicit_illumination(model, settings);
            spdlog::info("Luft 2007 illumination baked: {} generators, mean k_a {:.3f} (in COLOR_0)", report.generators,
                         report.mean_ka);
        }
        export_plant_glb(model, lod, o.out);
        spdlog::info("wrote {} ({} seed {}, {} level, {} triangles)", o.out, o.species, o.seed,
                     o.lod, model.lods[std::size_t(lod)].triangle_count());
    } catch (const std::exception& e) {
        spdlog::error("{}", e.what());
        return k_exit_failure;
    }
    return k_exit_ok;
}

}  // namespace

command_runner add_plant_command(CLI::App& app) {
    auto options = std::make_shared<plant_options>();
    app.add_option("species", options->species, "Species preset (see --list)");
    app.add_option("--seed", options->seed, "Seed: the same species and seed give the same plant")
        ->capture_default_str();
    app.add_option("--lod", options->lod, "Level of detail to write")
        ->check(CLI::IsMember({"full", "reduced", "far"}))
        ->capture_default_str();
    app.add_option("--texture-size", options->texture_size, "Leaf and bark texture size in texels")
        ->check(CLI::Range(16u, 4096u))
        ->capture_default_str();
    app.add_option("--out", options->out, "Output file (.glb)");
    app.add_flag("--implicit", options->implicit,
                 "Bake Luft 2007's implicit-surface illumination first: realigned normals, and the ambient "
                 "coefficient k_a as the vertex colour COLOR_0 (grey)");
    app.add_flag("--list", options->list, "Print the species presets and exit");
    return [options] { return plant(*options); };
}

}  // namespace sylva
