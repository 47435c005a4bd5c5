#pragma once
// A uniform grid over an area for dart throwing with a minimum spacing (the background grid of
// Bridson 2007 "Fast Poisson disk sampling in arbitrary dimensions", cells no smaller than the
// spacing so a conflicting point can only be in the 3x3 cells around a candidate). Used by
// models/terrain/placement.h and models/terrain/wang_tiles.h.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/vec2.hpp>
#include <limits>
#include <utility>
#include <vector>

namespace sylva {

// The acceleration grid is capped so a huge area with a tiny spacing cannot exhaust memory;
// cells then hold several points (linked lists), which stays correct, only slower.
inline constexpr double k_max_grid_cells = 4.0 * 1024.0 * 1024.0;
inline constexpr std::uint32_t k_no_grid_point = std::numeric_limits<std::uint32_t>::max();

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
        m_heads.assign(std::size_t(m_columns) * m_rows, k_no_grid_point);
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
                for (std::uint32_t i = m_heads[std::size_t(r) * m_columns + c]; i != k_no_grid_point; i = m_next[i])
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

}  // namespace sylva
