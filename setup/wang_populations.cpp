#include "setup/wang_populations.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "models/random.h"
#include "scenarios/species_lookup.h"

namespace sylva {

std::uint64_t wang_tiling_seed(const scenario& s) { return hash_combine(s.seed, 0x7a11ULL); }

glm::dvec2 wang_lattice_origin(const scenario& s) {
    const double half = 0.5 * s.terrain.size_m;
    return {-half, -half};
}

float wang_reach_m(const scenario& s, std::size_t p, const scene_assets& assets) {
    const population_settings& pop = s.populations.at(p);
    const std::size_t species = species_index_of(s, pop.species);
    const mesh_data& full = assets.meshes.at(assets.library.species.at(species).mesh_full);
    float reach = 0.0f;
    for (const vertex& v : full.vertices) reach = std::max(reach, std::hypot(v.position.x, v.position.z));
    return reach * pop.scale_max;
}

wang_tile_set wang_tile_set_of(const scenario& s, std::size_t p, float reach_m) {
    const population_settings& pop = s.populations.at(p);
    wang_tile_rules rules;
    rules.tile_size_m = s.wang_tiles.tile_size_m;
    rules.colours = s.wang_tiles.colours;
    rules.min_spacing_m = pop.min_spacing_m;
    rules.plants_per_m2 = double(pop.count) / ((pop.area[2] - pop.area[0]) * (pop.area[3] - pop.area[1]));
    rules.scale_min = pop.scale_min;
    rules.scale_max = pop.scale_max;
    rules.reach_m = reach_m;
    if (const std::string problem = wang_rules_problem(rules); !problem.empty())
        throw std::runtime_error(s.source + ": /populations/" + std::to_string(p) + " (" + pop.species +
                                 "): " + problem + "; raise wang_tiles.tile_size_m or lower the spacing");
    return build_wang_tile_set(rules, hash_combine(s.seed, std::uint64_t(p), 0x3a49ULL));
}

std::vector<placement> place_wang_population(const scenario& s, std::size_t p, float reach_m) {
    return place_wang_tiles(wang_tile_set_of(s, p, reach_m), wang_tiling_seed(s), wang_lattice_origin(s),
                            s.populations.at(p).area);
}

}  // namespace sylva
