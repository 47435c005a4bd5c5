#include "setup/wang_populations.h"

#include "models/random.h"

namespace sylva {

std::uint64_t wang_tiling_seed(const scenario& s) { return hash_combine(s.seed, 0x7a11ULL); }

glm::dvec2 wang_lattice_origin(const scenario& s) {
    const double half = 0.5 * s.terrain.size_m;
    return {-half, -half};
}

wang_tile_set wang_tile_set_of(const scenario& s, std::size_t p) {
    const population_settings& pop = s.populations.at(p);
    wang_tile_rules rules;
    rules.tile_size_m = s.wang_tiles.tile_size_m;
    rules.colours = s.wang_tiles.colours;
    rules.min_spacing_m = pop.min_spacing_m;
    rules.plants_per_m2 = double(pop.count) / ((pop.area[2] - pop.area[0]) * (pop.area[3] - pop.area[1]));
    rules.scale_min = pop.scale_min;
    rules.scale_max = pop.scale_max;
    return build_wang_tile_set(rules, hash_combine(s.seed, std::uint64_t(p), 0x3a49ULL));
}

std::vector<placement> place_wang_population(const scenario& s, std::size_t p) {
    return place_wang_tiles(wang_tile_set_of(s, p), wang_tiling_seed(s), wang_lattice_origin(s), s.populations.at(p).area);
}

}  // namespace sylva
