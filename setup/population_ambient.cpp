#include "setup/population_ambient.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>
#include <memory>
#include <nanoflann.hpp>
#include <vector>

#include "components/bounds.h"
#include "components/plant_instance.h"
#include "ecs/parallel.h"
#include "models/bake/nanoflann_points.h"

namespace sylva {
namespace {

// The neighbours' sphere centres are float relative to one plant: a landscape is a few
// kilometres, so float keeps millimetres.
using centre_cloud = nanoflann_points;
using centre_tree = point_kd_tree;

// The box corner c (ix + 2 iy + 4 iz) of [-h, h] x [0, 2h] x [-h, h].
glm::vec3 corner(int c, float h) {
    return {(c & 1) ? h : -h, (c & 2) ? 2.0f * h : 0.0f, (c & 4) ? h : -h};
}

glm::dvec3 to_world(const world_transform& t, glm::vec3 p) {
    // shaders/instance.glsl pose_instance: rotation mat3(c, 0, -s, 0, 1, 0, s, 0, c) (columns).
    const double c = std::cos(double(t.yaw)), s = std::sin(double(t.yaw));
    const glm::dvec3 q = glm::dvec3(p) * double(t.scale);
    return t.position + glm::dvec3(c * q.x + s * q.z, q.y, -s * q.x + c * q.z);
}

}  // namespace

species_density species_density_of(const plant_model& unscaled, const implicit_settings& settings, float scale,
                                   bool receives) {
    species_density out;
    out.receives = receives;
    out.generators = foliage_generators(unscaled.lods[0], settings.generator_fraction, settings.seed);
    out.used = implicit_defaults(out.generators, settings);
    for (glm::vec3& g : out.generators) g *= scale;
    out.used.rho_m *= scale;
    float h = 1e-3f;
    for (const vertex& v : unscaled.lods[0].vertices)
        h = std::max({h, std::abs(v.position.x), std::abs(v.position.z), 0.5f * v.position.y});
    out.half_size_m = h * scale;
    out.scale = scale;
    return out;
}

glm::vec3 to_model(const world_transform& t, const glm::dvec3& x) {
    const glm::dvec3 d = (x - t.position) / double(t.scale);
    const double c = std::cos(double(t.yaw)), s = std::sin(double(t.yaw));
    return glm::vec3(glm::dvec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z));
}

std::array<float, k_population_corners> population_factors(const placed_field& self, const implicit_settings& settings,
                                                           float half_size_m, std::span<const placed_field> neighbours) {
    std::array<float, k_population_corners> out{};
    for (int c = 0; c < k_population_corners; ++c) {
        const glm::dvec3 x = to_world(self.transform, corner(c, half_size_m));
        const float own = self.field->value(to_model(self.transform, x));
        float others = 0.0f;  // Σ_j (F_j + τ_j): the neighbours' Eq. 3 sums, in the given order
        for (const placed_field& n : neighbours) others += n.field->value(to_model(n.transform, x)) + n.field->tau();
        // Eq. 4 of the population's field over Eq. 4 of the plant's own (never 0: k_a,min may be).
        const float alone = ambient_coefficient(own, settings.ka_min, settings.d_min, settings.exponent);
        const float together = ambient_coefficient(own + others, settings.ka_min, settings.d_min, settings.exponent);
        out[std::size_t(c)] = alone > 0.0f ? std::min(together / alone, 1.0f) : 1.0f;
    }
    return out;
}

population_report bake_population_ambient(ecs::world& world, const scene_assets& assets) {
    population_report report;
    const auto start = std::chrono::steady_clock::now();
    if (!has_population_receivers(assets)) return report;
    const auto& transform_table = world.table<world_transform>();
    const auto& instance_table = world.table<plant_instance>();
    const auto& bounds_table = world.table<bounds>();
    const std::size_t n = transform_table.size();
    const world_transform* transforms = transform_table.data();
    const plant_instance* instances = instance_table.data();
    const bounds* spheres = bounds_table.data();

    // Every implicit-lit species' field, model space at its scale.
    std::vector<std::unique_ptr<implicit_field>> fields(assets.densities.size());
    for (std::size_t s = 0; s < assets.densities.size(); ++s) {
        const species_density& d = assets.densities[s];
        if (!d.generators.empty()) fields[s] = std::make_unique<implicit_field>(d.generators, d.used.rho_m, d.used.tau);
    }
    auto density_of = [&](std::size_t plant) -> const species_density* {
        const auto s = static_cast<std::size_t>(instances[plant].species);
        return s < fields.size() && fields[s] ? &assets.densities[s] : nullptr;
    };

    // The neighbours: every implicit-lit plant, by the centre of its bounding sphere; its field
    // reaches ρ beyond its generators, which lie inside that sphere.
    const glm::dvec3 origin = n > 0 ? transforms[0].position : glm::dvec3(0.0);
    std::vector<glm::vec3> centres;
    std::vector<std::uint32_t> plant_of;
    std::vector<float> reach;
    float max_reach = 0.0f;
    for (std::size_t i = 0; i < n; ++i) {
        const species_density* d = density_of(i);
        if (!d) continue;
        centres.push_back(glm::vec3(transforms[i].position + glm::dvec3(0.0, spheres[i].center_height, 0.0) - origin));
        plant_of.push_back(std::uint32_t(i));
        reach.push_back(spheres[i].radius + d->used.rho_m * transforms[i].scale);
        max_reach = std::max(max_reach, reach.back());
    }
    const centre_cloud cloud{&centres};  // nanoflann keeps a reference to it
    centre_tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tree.buildIndex();

    std::vector<population_ambient> out(n);
    std::vector<std::uint32_t> pairs(n, 0), darkened(n, 0);
    std::vector<float> lowest(n, 1.0f);
    ecs::parallel_for_each_index(n, [&](std::size_t i) {
        const species_density* d = density_of(i);
        if (!d || !d->receives) return;
        const world_transform& t = transforms[i];
        const float h = d->half_size_m;
        const glm::vec3 centre = glm::vec3(to_world(t, {0.0f, h, 0.0f}) - origin);
        const float radius = std::sqrt(3.0f) * h * t.scale;
        std::vector<std::pair<std::uint32_t, float>> near;
        nanoflann::SearchParams params;
        params.sorted = false;
        const float r = radius + max_reach;
        tree.radiusSearch(&centre.x, r * r, near, params);
        std::sort(near.begin(), near.end());  // neighbour order: plant order, for any thread count
        std::vector<placed_field> neighbours;
        for (const auto& [k, d2] : near) {
            const std::uint32_t j = plant_of[k];
            if (j == i || std::sqrt(d2) >= radius + reach[k]) continue;
            neighbours.push_back({fields[static_cast<std::size_t>(instances[j].species)].get(), transforms[j]});
        }
        const placed_field self{fields[static_cast<std::size_t>(instances[i].species)].get(), t};
        const auto factors = population_factors(self, d->used, h, neighbours);
        out[i] = pack_population_ambient(factors, h);
        pairs[i] = std::uint32_t(neighbours.size());
        lowest[i] = *std::min_element(factors.begin(), factors.end());
        darkened[i] = lowest[i] < 1.0f ? 1u : 0u;
    });
    for (std::size_t i = 0; i < n; ++i) {
        const species_density* d = density_of(i);
        report.receivers += d && d->receives ? 1 : 0;
        report.neighbour_pairs += pairs[i];
        report.darkened += darkened[i];
        report.min_factor = std::min(report.min_factor, lowest[i]);
    }
    const auto& entities = transform_table.entities();
    std::vector<ecs::entity> order(entities.begin(), entities.end());
    for (std::size_t i = 0; i < n; ++i) world.emplace<population_ambient>(order[i], out[i]);
    world.align<world_transform, population_ambient>();
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace sylva
