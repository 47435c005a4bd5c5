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
//
// Eq. 4's d_v is the bake's (ambient_source: the depth below the iso-surface by default, or the
// paper's density F(v) with --ambient-from density); beside k_a the unclamped d_v, which bounds
// what any Eq. 4 mapping (k_a,min, d_min, n) can rank for that ρ and τ.
//
// Beside them, how smooth the occlusion itself is: each leaf vertex ranked by the mean occlusion
// of the other leaves' vertices within ρ/4 of it (the field's own grid cell). Where that ranks
// well and −F does not, the occlusion is a smooth function of position but not one the density
// field can give: the limit is Eq. 2-4's, not the rays' noise nor the vertex's own leaf.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
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
#include "models/bake/lodf_leaves.h"
#include "models/bake/nanoflann_points.h"
#include "models/bake/radiance_transfer.h"
#include "scenarios/scenario.h"

namespace sylva {
namespace {

struct implicit_ao_options {
    std::vector<std::string> models;
    std::uint32_t rays = 256;
    std::uint64_t seed = 1;
    implicit_settings implicit;  // 0 for rho/tau/d_min: the bake's defaults
    std::string ambient_from = "depth";  // implicit.source, one of k_ambient_sources
    std::string json;
};

struct ao_result {
    std::string name;
    std::size_t vertices = 0;
    double implicit_rho = 0.0;
    double ellipsoid_rho = 0.0;
    double unclamped_rho = 0.0;  // −d_v itself: the best any k_a falling with d_v can rank
    double foliage_rho = 0.0;  // k_a on the leaves' vertices alone
    double neighbours_rho = 0.0;  // the other leaves' occlusion within ρ/4 (leaves only)
    double ka_min_share = 0.0;  // vertices at k_a,min (tied: Eq. 4 saturates at d_min)
    double bark_share = 0.0;    // vertices not on a leaf: trunk and branches
    implicit_settings used;
    double bake_s = 0.0;  // bake_implicit_illumination on every level, on this machine's threads
};

// Every leaf vertex's card (models/bake/lodf_leaves.h: the foliage's connected pieces).
std::vector<std::uint32_t> leaf_cards(const mesh_data& mesh) {
    std::vector<std::uint32_t> card(mesh.vertices.size(), 0u);
    const std::vector<foliage_leaf> leaves = find_foliage_leaves(mesh);
    for (std::uint32_t l = 0; l < leaves.size(); ++l)
        for (const std::uint32_t t : leaves[l].triangles)
            for (std::size_t c = 0; c < 3; ++c) card[mesh.indices[3 * std::size_t(t) + c]] = l;
    return card;
}

// Spearman over leaf vertices of their occlusion against the mean occlusion of the other cards'
// vertices within `radius` (vertices with no such neighbour left out).
double neighbours_correlation(const mesh_data& mesh, const std::vector<bool>& leaf,
                              const std::vector<double>& visibility, float radius) {
    const std::vector<std::uint32_t> card = leaf_cards(mesh);
    std::vector<glm::vec3> points;
    std::vector<std::uint32_t> vertex;
    for (std::uint32_t v = 0; v < leaf.size(); ++v)
        if (leaf[v]) points.push_back(mesh.vertices[v].position), vertex.push_back(v);
    const nanoflann_points cloud{&points};
    point_kd_tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    nanoflann::SearchParams params;
    params.sorted = false;
    std::vector<double> predicted, own;
    std::vector<std::pair<std::uint32_t, float>> near;
    for (std::size_t k = 0; k < points.size(); ++k) {
        tree.radiusSearch(&points[k].x, radius * radius, near, params);
        double sum = 0.0;
        std::size_t n = 0;
        for (const auto& [i, d2] : near)
            if (card[vertex[i]] != card[vertex[k]]) sum += visibility[vertex[i]], ++n;
        if (n == 0) continue;
        predicted.push_back(sum / double(n));
        own.push_back(visibility[vertex[k]]);
    }
    return spearman_correlation(predicted, own);
}

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
    implicit_settings implicit = o.implicit;
    implicit.source = ambient_source_named(o.ambient_from);
    implicit.seed = o.seed;
    const auto start = std::chrono::steady_clock::now();
    const implicit_report report = bake_implicit_illumination(plant, implicit);
    const double bake_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<double> ka(original.vertices.size());
    std::size_t at_min = 0;
    for (std::size_t v = 0; v < ka.size(); ++v) {
        ka[v] = glm::length(plant.lods[0].vertices[v].normal);
        at_min += ka[v] <= double(report.used.ka_min) + 1e-4 ? 1 : 0;
    }
    // d_v itself, unclamped: Eq. 4 is monotone in d_v, so −d_v bounds what any (k_a,min, d_min,
    // n) can reach for this ρ and τ.
    const implicit_field field(foliage_generators(original, implicit.generator_fraction, implicit.seed),
                               report.used.rho_m, report.used.tau);
    std::vector<double> unclamped(ka.size());
    if (report.used.source == ambient_source::density) {
        for (std::size_t v = 0; v < ka.size(); ++v)
            unclamped[v] = -double(field.value(original.vertices[v].position));
    } else {
        const density_grid grid =
            sample_density(field, report.used.rho_m / report.used.cells_per_rho);
        const iso_surface surface = extract_iso_surface(field, grid);
        std::vector<glm::vec3> positions(ka.size());
        for (std::size_t v = 0; v < ka.size(); ++v) positions[v] = original.vertices[v].position;
        const std::vector<float> depths =
            depths_below_surface(positions, grid, surface, report.used.tau);
        for (std::size_t v = 0; v < ka.size(); ++v)
            unclamped[v] = surface.positions.empty() ? 0.0 : -double(depths[v]);
    }
    // The naive method: 1 − the vertex's radial depth inside the foliage's axis-aligned bounding
    // ellipsoid (1 at its rim, 0 at its centre).
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (std::size_t v = 0; v < leaf.size(); ++v)
        if (leaf[v]) lo = glm::min(lo, original.vertices[v].position), hi = glm::max(hi, original.vertices[v].position);
    const glm::vec3 centre = 0.5f * (lo + hi), half = glm::max(0.5f * (hi - lo), glm::vec3(1e-4f));
    std::vector<double> ellipsoid(ka.size());
    for (std::size_t v = 0; v < ka.size(); ++v)
        ellipsoid[v] = std::min(1.0, double(glm::length((original.vertices[v].position - centre) / half)));
    ao_result r;
    r.name = plant_argument_name(argument);
    r.vertices = ka.size();
    r.implicit_rho = spearman_correlation(ka, visibility);
    r.ellipsoid_rho = spearman_correlation(ellipsoid, visibility);
    r.unclamped_rho = spearman_correlation(unclamped, visibility);
    std::vector<double> leaf_ka, leaf_visibility;
    for (std::size_t v = 0; v < ka.size(); ++v)
        if (leaf[v]) leaf_ka.push_back(ka[v]), leaf_visibility.push_back(visibility[v]);
    r.foliage_rho = spearman_correlation(leaf_ka, leaf_visibility);
    r.neighbours_rho =
        neighbours_correlation(original, leaf, visibility, 0.25f * report.used.rho_m);
    r.ka_min_share = double(at_min) / double(std::max<std::size_t>(ka.size(), 1));
    r.bark_share = 1.0 - double(leaf_ka.size()) / double(std::max<std::size_t>(ka.size(), 1));
    r.used = report.used;
    r.bake_s = bake_s;
    return r;
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
    const bool depth = ambient_source_named(o.ambient_from) == ambient_source::depth;
    std::printf("%-16s %9s | %12s %12s %12s %12s %12s | %9s | %7s %9s %9s | %6s\n", "model",
                "vertices", "Spearman k_a", "ellipsoid", depth ? "-depth bound" : "-F (bound)",
                "leaves only", "neighbours", "at k_amin", "rho m", "tau",
                depth ? "d_min m" : "d_min", "bake s");
    nlohmann::ordered_json json = nlohmann::ordered_json::array();
    for (const ao_result& r : results) {
        std::printf(
            "%-16s %9zu | %12.3f %12.3f %12.3f %12.3f %12.3f | %8.1f%% | %7.3f %9.4f %9.4f | "
            "%6.2f\n",
            r.name.c_str(), r.vertices, r.implicit_rho, r.ellipsoid_rho, r.unclamped_rho,
            r.foliage_rho, r.neighbours_rho, 100.0 * r.ka_min_share, r.used.rho_m, r.used.tau,
            depth ? r.used.depth_min_m : r.used.d_min, r.bake_s);
        json.push_back({{"model", r.name},
                        {"vertices", r.vertices},
                        {"spearman_implicit", r.implicit_rho},
                        {"spearman_ellipsoid", r.ellipsoid_rho},
                        {"ambient_from", depth ? "depth" : "density"},
                        {"spearman_unclamped", r.unclamped_rho},
                        {"spearman_foliage", r.foliage_rho},
                        {"spearman_neighbours", r.neighbours_rho},
                        {"ka_min_share", r.ka_min_share},
                        {"bark_share", r.bark_share},
                        {"rho_m", r.used.rho_m},
                        {"tau", r.used.tau},
                        {"d_min", r.used.d_min},
                        {"depth_min_m", r.used.depth_min_m},
                        {"bake_s", r.bake_s},
                        {"rays", o.rays}});
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
    app.add_option("--rho", options->implicit.rho_m, "Radius of influence rho in metres (Eq. 2; 0: the bake's default)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--tau", options->implicit.tau, "Threshold tau (Eq. 3; 0: the bake's default)")
        ->check(CLI::NonNegativeNumber);
    app.add_option(
           "--ambient-from", options->ambient_from,
           "Eq. 4's d_v: depth (below the iso-surface; the default) or density (F, the paper's)")
        ->check(CLI::IsMember(
            std::vector<std::string>(k_ambient_sources.begin(), k_ambient_sources.end())))
        ->capture_default_str();
    app.add_option("--d-min", options->implicit.d_min,
                   "d_min of Eq. 4 for density (0: the bake's default)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--depth-min", options->implicit.depth_min_m,
                   "d_min of Eq. 4 for depth, in metres (0: the bake's default)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--generator-fraction", options->implicit.generator_fraction,
                   "Share of foliage triangles that are generators (§3.1)")
        ->check(CLI::Range(0.001f, 1.0f))
        ->capture_default_str();
    app.add_option("--json", options->json, "Also write the table as JSON to this file");
    return [options] { return implicit_ao(*options); };
}

}  // namespace sylva
