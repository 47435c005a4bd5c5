#include "models/placement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "models/random.h"

namespace sylva {
namespace {

constexpr double k_two_pi = 6.283185307179586477;
// Darts thrown per requested plant before giving up: at 30 a population that fits easily is
// always complete, and a packed one ends after a bounded time.
constexpr std::uint64_t k_attempts_per_plant = 30;
// The acceleration grid is capped so a huge area with a tiny spacing cannot exhaust memory;
// cells then hold several points (linked lists), which stays correct, only slower.
constexpr double k_max_grid_cells = 4.0 * 1024.0 * 1024.0;
constexpr std::uint32_t k_none = std::numeric_limits<std::uint32_t>::max();

// Uniform grid of cells no smaller than the spacing, so a conflicting point can only be in the
// 3x3 cells around a candidate. Each cell heads a singly linked list of placed points.
class spacing_grid {
public:
    spacing_grid(const std::array<double, 4>& area, double spacing, std::uint32_t count)
        : m_origin_x(area[0]), m_origin_z(area[1]), m_spacing_sq(spacing * spacing) {
        const double width = area[2] - area[0];
        const double depth = area[3] - area[1];
        const double cap = std::min(k_max_grid_cells, 4.0 * std::max(count, 1u));
        m_cell = std::max(spacing, std::sqrt(width * depth / cap));
        m_columns = static_cast<std::uint32_t>(std::ceil(width / m_cell)) + 1;
        m_rows = static_cast<std::uint32_t>(std::ceil(depth / m_cell)) + 1;
        m_heads.assign(std::size_t(m_columns) * m_rows, k_none);
        m_next.reserve(count);
        m_points.reserve(count);
    }

    bool has_room(glm::dvec2 p) const {
        const auto [column, row] = cell_of(p);
        const std::uint32_t c0 = column > 0 ? column - 1 : 0;
        const std::uint32_t r0 = row > 0 ? row - 1 : 0;
        const std::uint32_t c1 = std::min(column + 1, m_columns - 1);
        const std::uint32_t r1 = std::min(row + 1, m_rows - 1);
        for (std::uint32_t r = r0; r <= r1; ++r)
            for (std::uint32_t c = c0; c <= c1; ++c)
                for (std::uint32_t i = m_heads[std::size_t(r) * m_columns + c]; i != k_none; i = m_next[i])
                    if (distance_sq(m_points[i], p) < m_spacing_sq) return false;
        return true;
    }

    void insert(glm::dvec2 p) {
        const auto [column, row] = cell_of(p);
        const std::size_t cell = std::size_t(row) * m_columns + column;
        m_next.push_back(m_heads[cell]);
        m_heads[cell] = static_cast<std::uint32_t>(m_points.size());
        m_points.push_back(p);
    }

private:
    static double distance_sq(glm::dvec2 a, glm::dvec2 b) {
        const glm::dvec2 d = a - b;
        return d.x * d.x + d.y * d.y;
    }

    std::pair<std::uint32_t, std::uint32_t> cell_of(glm::dvec2 p) const {
        const auto column = static_cast<std::uint32_t>((p.x - m_origin_x) / m_cell);
        const auto row = static_cast<std::uint32_t>((p.y - m_origin_z) / m_cell);
        return {std::min(column, m_columns - 1), std::min(row, m_rows - 1)};
    }

    double m_origin_x;
    double m_origin_z;
    double m_spacing_sq;
    double m_cell = 1.0;
    std::uint32_t m_columns = 1;
    std::uint32_t m_rows = 1;
    std::vector<std::uint32_t> m_heads;
    std::vector<std::uint32_t> m_next;
    std::vector<glm::dvec2> m_points;
};

placement make_placement(glm::dvec2 xz, float scale_min, float scale_max, rng& random) {
    placement p;
    p.xz = xz;
    p.scale = random.uniform(scale_min, scale_max);
    p.yaw = static_cast<float>(random.uniform_double() * k_two_pi);
    p.seed = random.next_u32();
    p.tint = static_cast<std::uint16_t>(random.next_u32() >> 16);
    return p;
}

// lo + (hi - lo) * u can round up to hi; the contract is the half-open interval.
double inside(double value, double hi) { return std::min(value, std::nextafter(hi, -std::numeric_limits<double>::infinity())); }

void validate(const std::array<double, 4>& area, float min_spacing_m) {
    if (!(area[0] < area[2]) || !(area[1] < area[3]))
        throw std::invalid_argument("place_population: area must have x0 < x1 and z0 < z1");
    if (!(min_spacing_m >= 0.0f)) throw std::invalid_argument("place_population: min_spacing_m must be >= 0");
}

}  // namespace

std::vector<placement> place_population(const heightfield& terrain, std::array<double, 4> area,
                                        std::uint32_t count, float min_spacing_m, float scale_min,
                                        float scale_max, float max_slope_deg, std::uint64_t seed) {
    validate(area, min_spacing_m);
    std::vector<placement> result;
    if (count == 0) return result;
    result.reserve(count);
    spacing_grid grid(area, min_spacing_m, count);
    rng random(seed);
    const std::uint64_t max_attempts = std::uint64_t(count) * k_attempts_per_plant + 100;
    for (std::uint64_t attempt = 0; attempt < max_attempts && result.size() < count; ++attempt) {
        // Both coordinates are drawn on every attempt, so the sequence of candidates (and hence
        // the result) depends on nothing but the seed.
        const glm::dvec2 xz{inside(random.uniform_double(area[0], area[2]), area[2]),
                            inside(random.uniform_double(area[1], area[3]), area[3])};
        if (!grid.has_room(xz)) continue;
        if (terrain.resolution >= 2 && terrain.slope_deg_at(xz.x, xz.y) > max_slope_deg) continue;
        grid.insert(xz);
        result.push_back(make_placement(xz, scale_min, scale_max, random));
    }
    return result;
}

}  // namespace sylva
