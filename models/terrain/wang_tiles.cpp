#include "models/terrain/wang_tiles.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "models/random.h"
#include "models/terrain/spacing_grid.h"

namespace sylva {
namespace {

// Darts thrown per expected plant before a region is left as it is: at 30 a region that fits
// its plants easily is always complete, a packed one ends after a bounded time (as
// models/terrain/placement.cpp).
constexpr double k_attempts_per_plant = 30.0;

enum class strip_direction : std::uint64_t { along_x = 1, along_z = 2 };

// A point of a shared set in its own frame: a corner's (x, z) from the corner; a strip's (along,
// across) from its first corner.
struct set_point {
    glm::dvec2 at;
    placement plant;
};

// The largest double below hi, for coordinates that must stay in [0, T).
double below(double value, double hi) {
    return std::min(value, std::nextafter(hi, -std::numeric_limits<double>::infinity()));
}

// Throws darts into `box` = {x0, z0, x1, z1} for `expected` plants (its integer part, plus one
// with the probability of its fraction), keeping a candidate that `inside` accepts and that has
// room in `grid`.
template <class Inside>
void throw_darts(rng& random, const std::array<double, 4>& box, double expected, const wang_tile_rules& rules,
                 const Inside& inside, spacing_grid& grid, std::vector<set_point>& out) {
    const double whole = std::floor(expected);
    auto count = std::uint64_t(whole);
    if (random.uniform_double() < expected - whole) ++count;
    const auto attempts = std::uint64_t(std::ceil(double(count) * k_attempts_per_plant));
    std::uint64_t placed = 0;
    for (std::uint64_t a = 0; a < attempts && placed < count; ++a) {
        const glm::dvec2 p{below(random.uniform_double(box[0], box[2]), box[2]),
                           below(random.uniform_double(box[1], box[3]), box[3])};
        if (!inside(p) || !grid.has_room(p)) continue;
        grid.insert(p);
        out.push_back({p, make_placement(p, rules.scale_min, rules.scale_max, random)});
        ++placed;
    }
}

std::uint32_t grid_capacity(double area_m2, const wang_tile_rules& rules) {
    return std::uint32_t(std::min(1e7, area_m2 * rules.plants_per_m2 + 16.0));
}

// The Poisson set around a corner of colour `colour`: the square [−m, m)².
std::vector<set_point> corner_set(const wang_tile_rules& rules, const wang_margins& g, std::uint64_t seed,
                                  std::uint32_t colour) {
    std::vector<set_point> out;
    if (!(g.corner > 0.0)) return out;
    const double m = g.corner;
    const std::array<double, 4> box{-m, -m, m, m};
    spacing_grid grid(box, rules.min_spacing_m, grid_capacity(4.0 * m * m, rules));
    rng random(hash_combine(seed, 0xc0ULL, colour));
    throw_darts(random, box, rules.plants_per_m2 * 4.0 * m * m, rules, [](glm::dvec2) { return true; }, grid, out);
    return out;
}

// The set along an edge whose first corner has colour a and second colour b: the strip
// [m, T − m) x [−w, w) in (along, across), thrown around both corners' sets.
std::vector<set_point> strip_set(const wang_tile_rules& rules, const wang_margins& g, std::uint64_t seed,
                                 strip_direction direction, const std::vector<set_point>& first,
                                 const std::vector<set_point>& second, std::uint32_t a, std::uint32_t b) {
    std::vector<set_point> out;
    const double t = rules.tile_size_m;
    const double m = g.corner;
    const double w = g.strip;
    if (!(w > 0.0)) return out;
    spacing_grid grid({-m, -m, t + m, m}, rules.min_spacing_m,
                      grid_capacity((t + 2.0 * m) * 2.0 * m, rules));
    // A corner point (x, z) in the strip's (along, across): x along x, z along z.
    const auto frame = [direction](glm::dvec2 p) { return direction == strip_direction::along_x ? p : glm::dvec2(p.y, p.x); };
    for (const set_point& p : first) grid.insert(frame(p.at));
    for (const set_point& p : second) grid.insert(frame(p.at) + glm::dvec2(t, 0.0));
    rng random(hash_combine(seed, 0x57ULL, std::uint64_t(direction), a, b));
    throw_darts(random, {m, -w, t - m, w}, rules.plants_per_m2 * (t - 2.0 * m) * 2.0 * w, rules,
                [](glm::dvec2) { return true; }, grid, out);
    return out;
}

}  // namespace

std::array<std::uint32_t, 4> wang_tile_corners(std::uint32_t colours, std::uint32_t index) {
    std::array<std::uint32_t, 4> c{};
    for (std::uint32_t& v : c) {
        v = index % colours;
        index /= colours;
    }
    return c;
}

std::uint32_t wang_corner_colour(std::uint64_t seed, std::int64_t i, std::int64_t j, std::uint32_t colours) {
    const std::uint64_t h = hash_combine(seed, std::uint64_t(i), std::uint64_t(j));
    return std::uint32_t(((h >> 32) * colours) >> 32);  // the high bits, without modulo bias
}

std::uint32_t wang_tile_at(std::uint64_t seed, std::int64_t i, std::int64_t j, std::uint32_t colours) {
    return wang_tile_index(colours, wang_corner_colour(seed, i, j, colours), wang_corner_colour(seed, i + 1, j, colours),
                           wang_corner_colour(seed, i, j + 1, colours), wang_corner_colour(seed, i + 1, j + 1, colours));
}

wang_tile_set build_wang_tile_set(const wang_tile_rules& rules, std::uint64_t seed) {
    if (const std::string problem = wang_rules_problem(rules); !problem.empty())
        throw std::invalid_argument("Wang tiles: " + problem);
    const std::uint32_t colours = rules.colours;
    const double t = rules.tile_size_m;
    const wang_margins g = wang_margins_for(rules.min_spacing_m, rules.reach_m);
    std::vector<std::vector<set_point>> corners(colours);
    for (std::uint32_t c = 0; c < colours; ++c) corners[c] = corner_set(rules, g, seed, c);
    // strips[direction][a * C + b]
    std::array<std::vector<std::vector<set_point>>, 2> strips;
    for (std::size_t d = 0; d < 2; ++d) {
        const auto direction = d == 0 ? strip_direction::along_x : strip_direction::along_z;
        for (std::uint32_t a = 0; a < colours; ++a)
            for (std::uint32_t b = 0; b < colours; ++b)
                strips[d].push_back(strip_set(rules, g, seed, direction, corners[a], corners[b], a, b));
    }
    wang_tile_set set;
    set.rules = rules;
    const std::uint32_t count = colours * colours * colours * colours;
    set.tiles.resize(count);
    set.reaching.resize(count);
    for (std::uint32_t index = 0; index < count; ++index) {
        const auto [sw, se, nw, ne] = wang_tile_corners(colours, index);
        std::vector<set_point> mine;
        std::vector<placement>& reaching = set.reaching[index];
        // The tile's share of each shared set, moved into tile coordinates [0, T)²; the rest of
        // the set, moved the same way, may reach in.
        const auto take = [&](const std::vector<set_point>& from, auto owns, auto to_tile) {
            for (const set_point& p : from) {
                const glm::dvec2 at = to_tile(p.at);
                if (owns(p.at)) {
                    mine.push_back({{below(at.x, t), below(at.y, t)}, p.plant});
                } else {
                    placement plant = p.plant;
                    plant.xz = at;
                    reaching.push_back(plant);
                }
            }
        };
        const auto ahead = [](double v) { return v >= 0.0; };
        take(corners[sw], [&](glm::dvec2 p) { return ahead(p.x) && ahead(p.y); }, [](glm::dvec2 p) { return p; });
        take(corners[se], [&](glm::dvec2 p) { return !ahead(p.x) && ahead(p.y); }, [t](glm::dvec2 p) { return glm::dvec2(t + p.x, p.y); });
        take(corners[nw], [&](glm::dvec2 p) { return ahead(p.x) && !ahead(p.y); }, [t](glm::dvec2 p) { return glm::dvec2(p.x, t + p.y); });
        take(corners[ne], [&](glm::dvec2 p) { return !ahead(p.x) && !ahead(p.y); }, [t](glm::dvec2 p) { return glm::dvec2(t + p.x, t + p.y); });
        // Strips in (along, across): the bottom and top edges run along x, the left and right along z.
        take(strips[0][sw * colours + se], [&](glm::dvec2 p) { return ahead(p.y); }, [](glm::dvec2 p) { return p; });
        take(strips[0][nw * colours + ne], [&](glm::dvec2 p) { return !ahead(p.y); }, [t](glm::dvec2 p) { return glm::dvec2(p.x, t + p.y); });
        take(strips[1][sw * colours + nw], [&](glm::dvec2 p) { return ahead(p.y); }, [](glm::dvec2 p) { return glm::dvec2(p.y, p.x); });
        take(strips[1][se * colours + ne], [&](glm::dvec2 p) { return !ahead(p.y); }, [t](glm::dvec2 p) { return glm::dvec2(t + p.y, p.x); });
        // The interior: at least w from the border and outside the corner squares, thrown
        // around the shares above (every other point is at least w = r away).
        const double w = g.strip;
        const double m = g.corner;
        spacing_grid grid({0.0, 0.0, t, t}, rules.min_spacing_m, grid_capacity(t * t, rules) + std::uint32_t(mine.size()));
        for (const set_point& p : mine) grid.insert(p.at);
        const auto interior = [&](glm::dvec2 p) {
            const bool near_x = p.x < m || p.x >= t - m;
            const bool near_z = p.y < m || p.y >= t - m;
            return !(near_x && near_z);
        };
        rng random(hash_combine(seed, 0x71ULL, index));
        const double area = (t - 2.0 * w) * (t - 2.0 * w) - 4.0 * (m - w) * (m - w);
        throw_darts(random, {w, w, t - w, t - w}, rules.plants_per_m2 * area, rules, interior, grid, mine);
        std::vector<placement>& plants = set.tiles[index];
        plants.reserve(mine.size());
        for (const set_point& p : mine) {
            placement plant = p.plant;
            plant.xz = p.at;
            plants.push_back(plant);
        }
    }
    return set;
}

std::vector<placement> place_wang_tiles(const wang_tile_set& set, std::uint64_t tiling_seed, glm::dvec2 origin,
                                        const std::array<double, 4>& area) {
    const double t = set.rules.tile_size_m;
    const auto first = [&](double lo, double o) { return std::int64_t(std::floor((lo - o) / t)); };
    const auto last = [&](double hi, double o) { return std::int64_t(std::ceil((hi - o) / t)) - 1; };
    std::vector<placement> out;
    for (std::int64_t j = first(area[1], origin.y); j <= last(area[3], origin.y); ++j)
        for (std::int64_t i = first(area[0], origin.x); i <= last(area[2], origin.x); ++i) {
            const glm::dvec2 corner = origin + glm::dvec2(double(i) * t, double(j) * t);
            for (const placement& p : set.tiles[wang_tile_at(tiling_seed, i, j, set.rules.colours)]) {
                const glm::dvec2 xz = corner + p.xz;
                if (xz.x < area[0] || xz.x >= area[2] || xz.y < area[1] || xz.y >= area[3]) continue;
                placement world = p;
                world.xz = xz;
                out.push_back(world);
            }
        }
    return out;
}

}  // namespace sylva
