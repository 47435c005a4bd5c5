#include "models/terrain/placement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "models/random.h"
#include "models/terrain/spacing_grid.h"

namespace sylva {
namespace {

constexpr double k_two_pi = 6.283185307179586477;
// Darts thrown per requested plant before giving up: at 30 a population that fits easily is
// always complete, and a packed one ends after a bounded time.
constexpr std::uint64_t k_attempts_per_plant = 30;
// lo + (hi - lo) * u can round up to hi; the contract is the half-open interval.
double inside(double value, double hi) { return std::min(value, std::nextafter(hi, -std::numeric_limits<double>::infinity())); }

void validate(const std::array<double, 4>& area, float min_spacing_m) {
    if (!(area[0] < area[2]) || !(area[1] < area[3]))
        throw std::invalid_argument("place_population: area must have x0 < x1 and z0 < z1");
    if (!(min_spacing_m >= 0.0f)) throw std::invalid_argument("place_population: min_spacing_m must be >= 0");
}

// The per-candidate rules shared by both modes; `random` is advanced only when a density map
// is given, so the old (density-free) sequence of candidates is unchanged.
bool passes_rules(const heightfield& terrain, const placement_rules& rules, glm::dvec2 xz,
                  rng& random) {
    if (rules.density) {
        const double u = (xz.x - rules.area[0]) / (rules.area[2] - rules.area[0]);
        const double v = (xz.y - rules.area[1]) / (rules.area[3] - rules.area[1]);
        if (!(random.uniform_double() < double(rules.density->at(u, v)))) return false;
    }
    if (terrain.resolution < 2) return true;
    if (terrain.slope_deg_at(xz.x, xz.y) > rules.max_slope_deg) return false;
    const float altitude = terrain.height_at(xz.x, xz.y);
    return altitude >= rules.min_altitude_m && altitude <= rules.max_altitude_m;
}

std::vector<placement> place_darts(const heightfield& terrain, const placement_rules& rules,
                                   std::uint64_t seed) {
    const auto& area = rules.area;
    std::vector<placement> result;
    result.reserve(rules.count);
    spacing_grid grid(area, rules.min_spacing_m, rules.count);
    rng random(seed);
    const std::uint64_t max_attempts = std::uint64_t(rules.count) * k_attempts_per_plant + 100;
    for (std::uint64_t attempt = 0; attempt < max_attempts && result.size() < rules.count;
         ++attempt) {
        // Both coordinates are drawn on every attempt, so the sequence of candidates (and hence
        // the result) depends on nothing but the seed.
        const glm::dvec2 xz{inside(random.uniform_double(area[0], area[2]), area[2]),
                            inside(random.uniform_double(area[1], area[3]), area[3])};
        if (!grid.has_room(xz)) continue;
        if (!passes_rules(terrain, rules, xz, random)) continue;
        grid.insert(xz);
        result.push_back(make_placement(xz, rules.scale_min, rules.scale_max, random));
    }
    return result;
}

// Cells per side of the jittered grid: about sqrt(count * side / other side), but never
// narrower than the spacing.
std::uint32_t grid_cells(double side, double cell) {
    return static_cast<std::uint32_t>(std::max(1.0, std::floor(side / cell)));
}

std::vector<placement> place_jittered(const heightfield& terrain, const placement_rules& rules,
                                      std::uint64_t seed) {
    const auto& area = rules.area;
    const double width = area[2] - area[0];
    const double depth = area[3] - area[1];
    const double spacing = rules.min_spacing_m;
    const double cell = std::max(std::sqrt(width * depth / rules.count), spacing);
    const std::uint32_t columns = grid_cells(width, cell);
    const std::uint32_t rows = grid_cells(depth, cell);
    const double cell_w = width / columns;
    const double cell_d = depth / rows;
    // Points stay spacing/2 inside their cell, so points of different cells are >= spacing apart
    // along x or z (a cell narrower than the spacing happens only with a single column or row).
    const double margin_x = std::min(0.5 * spacing, 0.5 * cell_w);
    const double margin_z = std::min(0.5 * spacing, 0.5 * cell_d);
    std::vector<placement> result;
    result.reserve(std::min<std::size_t>(rules.count, std::size_t(columns) * rows));
    rng random(seed);
    for (std::uint32_t row = 0; row < rows && result.size() < rules.count; ++row) {
        for (std::uint32_t column = 0; column < columns && result.size() < rules.count; ++column) {
            const double x0 = area[0] + column * cell_w + margin_x;
            const double z0 = area[1] + row * cell_d + margin_z;
            const glm::dvec2 xz{
                inside(random.uniform_double(x0, x0 + cell_w - 2.0 * margin_x), area[2]),
                inside(random.uniform_double(z0, z0 + cell_d - 2.0 * margin_z), area[3])};
            if (!passes_rules(terrain, rules, xz, random)) continue;
            result.push_back(make_placement(xz, rules.scale_min, rules.scale_max, random));
        }
    }
    return result;
}

}  // namespace

placement make_placement(glm::dvec2 xz, float scale_min, float scale_max, rng& random) {
    placement p;
    p.xz = xz;
    p.scale = random.uniform(scale_min, scale_max);
    p.yaw = static_cast<float>(random.uniform_double() * k_two_pi);
    p.seed = random.next_u32();
    p.tint = static_cast<std::uint16_t>(random.next_u32() >> 16);
    return p;
}

std::vector<placement> place_population(const heightfield& terrain, const placement_rules& rules,
                                        std::uint64_t seed) {
    validate(rules.area, rules.min_spacing_m);
    if (rules.count == 0) return {};
    return rules.poisson ? place_darts(terrain, rules, seed) : place_jittered(terrain, rules, seed);
}

std::vector<placement> place_population(const heightfield& terrain, std::array<double, 4> area,
                                        std::uint32_t count, float min_spacing_m, float scale_min,
                                        float scale_max, float max_slope_deg, std::uint64_t seed) {
    placement_rules rules;
    rules.area = area;
    rules.count = count;
    rules.min_spacing_m = min_spacing_m;
    rules.scale_min = scale_min;
    rules.scale_max = scale_max;
    rules.max_slope_deg = max_slope_deg;
    return place_population(terrain, rules, seed);
}

}  // namespace sylva
