// `sylva implicit-ao MODEL... [--rays N] [--json FILE]`: how well Luft 2007's ambient
// coefficient (Eq. 4's k_a, baked as the normal's length) ranks a plant's vertices by how
// occluded they really are (issue 22): per vertex, the Spearman rank correlation between k_a and
// ambient occlusion ray-cast with Embree, against the same for the naive method the paper rejects
// (a vertex's depth inside the foliage's bounding ellipsoid).
//
// The occlusion is the cosine-weighted visibility of the vertex's hemisphere, both hemispheres
// of a two-sided leaf averaged (light reaches a leaf from either side; k_a does not know which):
// the first SH coefficient of the radiance transfer (models/bake/radiance_transfer.h) divided by
// its unoccluded value π·Y_00, so the rays and the leaves' alpha test are the transfer bake's.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/model_argument.h"
#include "io/atomic_file.h"
#include "measure/rank_correlation.h"
#include "models/bake/implicit_illumination.h"
#include "models/bake/radiance_transfer.h"

namespace sylva {
namespace {

struct implicit_ao_options {
    std::vector<std::string> models;
    std::uint32_t rays = 256;
    std::uint64_t seed = 1;
    std::string json;
};

struct ao_result {
    std::string name;
    std::size_t vertices = 0;
    double implicit_rho = 0.0;
    double ellipsoid_rho = 0.0;
};

ao_result measure(const std::string& argument, const implicit_ao_options& o) {
    plant_model plant = load_plant_argument(argument, o.seed, 64);
    const mesh_data original = plant.lods[0];
    // The ray-cast occlusion of the original geometry.
    const transfer_occluders occluders(original, plant.leaf_texture, plant.bark_texture);
    transfer_settings settings;
    settings.bands = 2;
    settings.rays_per_receiver = o.rays;
    settings.seed = o.seed;
    const radiance_transfer t = occluders.bake(original.vertices, settings);
    constexpr double k_unoccluded = 3.14159265358979 * 0.28209479177387814;  // ∫ max(n·ω, 0) Y_00
    std::vector<bool> leaf(original.vertices.size(), false);
    for (const submesh& s : original.submeshes)
        if (s.material == material_kind::leaf)
            for (std::uint32_t i = s.first_index; i < s.first_index + s.index_count; ++i) leaf[original.indices[i]] = true;
    std::vector<double> visibility(original.vertices.size());
    for (std::size_t v = 0; v < visibility.size(); ++v) {
        const double front = t.front[v * 4] / k_unoccluded, back = t.back[v * 4] / k_unoccluded;
        visibility[v] = leaf[v] ? 0.5 * (front + back) : front;
    }
    // Eq. 4's k_a, as the bake stores it.
    implicit_settings implicit;
    implicit.seed = o.seed;
    bake_implicit_illumination(plant, implicit);
    std::vector<double> ka(original.vertices.size());
    for (std::size_t v = 0; v < ka.size(); ++v) ka[v] = glm::length(plant.lods[0].vertices[v].normal);
    // The naive method: 1 − the vertex's radial depth inside the foliage's axis-aligned bounding
    // ellipsoid (1 at its rim, 0 at its centre).
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (std::size_t v = 0; v < leaf.size(); ++v)
        if (leaf[v]) lo = glm::min(lo, original.vertices[v].position), hi = glm::max(hi, original.vertices[v].position);
    const glm::vec3 centre = 0.5f * (lo + hi), half = glm::max(0.5f * (hi - lo), glm::vec3(1e-4f));
    std::vector<double> ellipsoid(ka.size());
    for (std::size_t v = 0; v < ka.size(); ++v)
        ellipsoid[v] = std::min(1.0, double(glm::length((original.vertices[v].position - centre) / half)));
    return {plant_argument_name(argument), ka.size(), spearman_correlation(ka, visibility), spearman_correlation(ellipsoid, visibility)};
}

int implicit_ao(const implicit_ao_options& o) {
    std::vector<ao_result> results;
    for (const std::string& m : o.models) {
        try {
            check_plant_argument(m);
            spdlog::info("{}: ray-casting {} rays per vertex", m, o.rays);
            results.push_back(measure(m, o));
        } catch (const std::invalid_argument& e) {
            spdlog::error("implicit-ao: {}", e.what());
            return k_exit_bad_input;
        } catch (const std::exception& e) {
            spdlog::error("implicit-ao: {}: {}", m, e.what());
            return k_exit_failure;
        }
    }
    std::printf("%-16s %9s | %18s %18s\n", "model", "vertices", "Spearman k_a", "Spearman ellipsoid");
    nlohmann::ordered_json json = nlohmann::ordered_json::array();
    for (const ao_result& r : results) {
        std::printf("%-16s %9zu | %18.3f %18.3f\n", r.name.c_str(), r.vertices, r.implicit_rho, r.ellipsoid_rho);
        json.push_back({{"model", r.name}, {"vertices", r.vertices}, {"spearman_implicit", r.implicit_rho},
                        {"spearman_ellipsoid", r.ellipsoid_rho}, {"rays", o.rays}});
    }
    if (!o.json.empty()) write_atomically(o.json, json.dump(2) + "\n");
    return k_exit_ok;
}

}  // namespace

command_runner add_implicit_ao_command(CLI::App& app) {
    auto options = std::make_shared<implicit_ao_options>();
    app.add_option("models", options->models, "Species presets (see `sylva plant --list`) or .gltf/.glb plants")
        ->required();
    app.add_option("--rays", options->rays, "Rays per vertex for the occlusion")
        ->check(CLI::Range(16u, 4096u))
        ->capture_default_str();
    app.add_option("--seed", options->seed, "Preset seed, and the rays' and generators' seed")->capture_default_str();
    app.add_option("--json", options->json, "Also write the table as JSON to this file");
    return [options] { return implicit_ao(*options); };
}

}  // namespace sylva
