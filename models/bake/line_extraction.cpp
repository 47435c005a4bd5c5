#include "models/bake/line_extraction.h"

#include "models/bake/implicit_illumination.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>

namespace sylva {
namespace {

// Stations split where the gap between consecutive vertices along the principal axis exceeds
// this fraction of the largest gap: a tube's rings or a strip's cross-sections are separated by
// the segment length, the vertices of one ring only by the ring's tilt.
constexpr float k_station_gap_fraction = 0.5f;
constexpr int k_power_iterations = 64;
// Below this share of its triangles' normals agreeing, an element has no surface normal (a
// tube: its normals cancel), and its lines take a side direction instead.
constexpr float k_surface_normal_agreement = 0.5f;

bool position_less(const glm::vec3& a, const glm::vec3& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];  // path halving
        i = parent[i];
    }
    return i;
}

// The element's vertex positions, each once: a tube's seam (u = 0 and u = 1 at the same place,
// up to rounding in sin 2π) or a uv seam would otherwise count twice and pull a station's
// centroid toward it. Positions closer than k_weld_fraction of the element's extent are one.
std::vector<glm::vec3> unique_positions(const mesh_data& mesh,
                                        std::span<const std::uint32_t> triangles) {
    constexpr float k_weld_fraction = 1e-5f;
    std::vector<glm::vec3> points;
    points.reserve(triangles.size() * 3);
    for (const std::uint32_t t : triangles)
        for (std::size_t k = 0; k < 3; ++k)
            points.push_back(mesh.vertices[mesh.indices[std::size_t(t) * 3 + k]].position);
    glm::vec3 lo = points.front();
    glm::vec3 hi = points.front();
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 extent = hi - lo;
    const float weld = k_weld_fraction * std::max({extent.x, extent.y, extent.z});
    if (!(weld > 0.0f)) return {points.front()};
    std::vector<std::pair<glm::vec3, glm::vec3>> keyed;  // (grid cell, position)
    keyed.reserve(points.size());
    for (const glm::vec3& p : points) keyed.emplace_back(glm::floor((p - lo) / weld + 0.5f), p);
    std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? position_less(a.first, b.first)
                                  : position_less(a.second, b.second);
    });
    std::vector<glm::vec3> unique;
    for (std::size_t i = 0; i < keyed.size(); ++i)
        if (i == 0 || keyed[i].first != keyed[i - 1].first) unique.push_back(keyed[i].second);
    return unique;
}

// The covariance's dominant eigenvector by power iteration, started from its largest column
// (in the matrix's range, so not orthogonal to the answer unless the spread is isotropic, when
// any axis will do).
glm::vec3 principal_axis(std::span<const glm::vec3> points, glm::dvec3 mean) {
    double c[3][3] = {};
    for (const glm::vec3& p : points) {
        const glm::dvec3 d = glm::dvec3(p) - mean;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) c[i][j] += d[i] * d[j];
    }
    glm::dvec3 v{1.0, 0.0, 0.0};
    double best = 0.0;
    for (int j = 0; j < 3; ++j) {
        const glm::dvec3 column{c[0][j], c[1][j], c[2][j]};
        if (glm::dot(column, column) > best) {
            best = glm::dot(column, column);
            v = column;
        }
    }
    if (best == 0.0) return {1.0f, 0.0f, 0.0f};
    for (int iteration = 0; iteration < k_power_iterations; ++iteration) {
        const glm::dvec3 next{c[0][0] * v.x + c[0][1] * v.y + c[0][2] * v.z,
                              c[1][0] * v.x + c[1][1] * v.y + c[1][2] * v.z,
                              c[2][0] * v.x + c[2][1] * v.y + c[2][2] * v.z};
        const double length = glm::length(next);
        if (length == 0.0) break;
        v = next / length;
    }
    return glm::vec3(glm::normalize(v));
}

float distance_to_segment(glm::vec3 p, glm::vec3 a, glm::vec3 b) {
    const glm::vec3 ab = b - a;
    const float length2 = glm::dot(ab, ab);
    const float s = length2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + s * ab));
}

float distance_to_polyline(glm::vec3 p, std::span<const glm::vec3> line) {
    float best = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i + 1 < line.size(); ++i)
        best = std::min(best, distance_to_segment(p, line[i], line[i + 1]));
    return best;
}

// Station centroids in order along the principal axis.
std::vector<glm::vec3> station_centroids(std::span<const glm::vec3> points) {
    glm::dvec3 mean{0.0};
    for (const glm::vec3& p : points) mean += glm::dvec3(p);
    mean /= double(points.size());
    const glm::vec3 axis = principal_axis(points, mean);
    std::vector<std::pair<float, std::uint32_t>> along(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i)
        along[i] = {glm::dot(points[i] - glm::vec3(mean), axis), i};
    std::sort(along.begin(), along.end());
    float largest_gap = 0.0f;
    for (std::size_t i = 1; i < along.size(); ++i)
        largest_gap = std::max(largest_gap, along[i].first - along[i - 1].first);
    if (largest_gap <= 0.0f) return {};
    const float split = k_station_gap_fraction * largest_gap;
    std::vector<glm::vec3> stations;
    glm::vec3 sum{0.0f};
    int count = 0;
    for (std::size_t i = 0; i < along.size(); ++i) {
        if (i > 0 && along[i].first - along[i - 1].first > split) {
            stations.push_back(sum / float(count));
            sum = glm::vec3{0.0f};
            count = 0;
        }
        sum += points[along[i].second];
        ++count;
    }
    stations.push_back(sum / float(count));
    return stations;
}

// Douglas & Peucker 1973: keep the station farthest from the chord while it is beyond the
// tolerance, recursively on both sides.
void simplify(std::span<const glm::vec3> line, std::size_t first, std::size_t last, float tolerance,
              std::vector<bool>& keep) {
    if (last <= first + 1) return;
    float farthest = -1.0f;
    std::size_t at = first;
    for (std::size_t i = first + 1; i < last; ++i) {
        const float d = distance_to_segment(line[i], line[first], line[last]);
        if (d > farthest) {
            farthest = d;
            at = i;
        }
    }
    if (farthest <= tolerance) return;
    keep[at] = true;
    simplify(line, first, at, tolerance, keep);
    simplify(line, at, last, tolerance, keep);
}

glm::vec3 across(glm::vec3 direction, glm::vec3 preferred) {
    const glm::vec3 n = preferred - glm::dot(preferred, direction) * direction;
    const float length = glm::length(n);
    return length > 1e-4f ? n / length : glm::vec3{0.0f};
}

// The line's normal (see build_element_lines).
glm::vec3 line_normal(glm::vec3 direction, glm::vec3 surface_normal) {
    glm::vec3 n = across(direction, surface_normal);
    if (n == glm::vec3{0.0f}) n = across(direction, {0.0f, 1.0f, 0.0f});
    if (n == glm::vec3{0.0f}) n = across(direction, {1.0f, 0.0f, 0.0f});
    return n;
}

// The vertex of `vertices` nearest to p: a line's colour is read at the opaque cell centre nearest
// its middle, and under Luft 2007 (models/bake/implicit_illumination.h), where the element's
// vertices carry realigned normals scaled by k_a, a line vertex takes the normal of the element's
// vertex nearest to it, length and all, so lines are lit by the crown's shape and darkened inside
// it as the mesh is.
// Ties go to the first vertex, so the choice does not depend on anything but the mesh.
// `vertices` is not empty (an element has triangles).
const vertex& nearest_vertex(const std::vector<vertex>& vertices, glm::vec3 p) {
    std::size_t best = 0;
    float nearest = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const glm::vec3 d = vertices[i].position - p;
        if (glm::dot(d, d) < nearest) {
            nearest = glm::dot(d, d);
            best = i;
        }
    }
    return vertices[best];
}

}  // namespace

std::vector<std::uint32_t> connected_elements(const mesh_data& mesh,
                                              std::span<const std::uint32_t> triangles,
                                              std::span<const std::uint64_t> group) {
    struct corner {
        glm::vec3 position;
        std::uint64_t group;
        std::uint32_t slot;  // index into `triangles`
    };
    std::vector<corner> corners;
    corners.reserve(triangles.size() * 3);
    for (std::uint32_t slot = 0; slot < triangles.size(); ++slot)
        for (std::size_t k = 0; k < 3; ++k)
            corners.push_back(
                {mesh.vertices[mesh.indices[std::size_t(triangles[slot]) * 3 + k]].position,
                 group[slot], slot});
    std::sort(corners.begin(), corners.end(), [](const corner& a, const corner& b) {
        if (a.group != b.group) return a.group < b.group;
        if (a.position != b.position) return position_less(a.position, b.position);
        return a.slot < b.slot;
    });
    std::vector<std::uint32_t> parent(triangles.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (std::size_t i = 1; i < corners.size(); ++i) {
        if (corners[i].group != corners[i - 1].group ||
            corners[i].position != corners[i - 1].position)
            continue;
        const std::uint32_t a = find_root(parent, corners[i - 1].slot);
        const std::uint32_t b = find_root(parent, corners[i].slot);
        parent[std::max(a, b)] =
            std::min(a, b);  // the smaller slot roots: independent of the sort's ties
    }
    constexpr std::uint32_t k_unassigned = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> id_of_root(triangles.size(), k_unassigned);
    std::vector<std::uint32_t> element(triangles.size());
    std::uint32_t next = 0;
    for (std::uint32_t slot = 0; slot < triangles.size(); ++slot) {
        const std::uint32_t root = find_root(parent, slot);
        if (id_of_root[root] == k_unassigned) id_of_root[root] = next++;
        element[slot] = id_of_root[root];
    }
    return element;
}

element_spine extract_spine(const mesh_data& mesh, std::span<const std::uint32_t> triangles) {
    element_spine out;
    const std::vector<glm::vec3> points = unique_positions(mesh, triangles);
    if (points.size() < 2) return out;
    const std::vector<glm::vec3> stations = station_centroids(points);
    if (stations.size() < 2) return out;
    float spread = 0.0f;
    for (const glm::vec3& p : points) {
        const float d = distance_to_polyline(p, stations);
        spread += d;
        out.thickness = std::max(out.thickness, 2.0f * d);
    }
    out.width = 2.0f * spread / float(points.size());
    std::vector<bool> keep(stations.size(), false);
    keep.front() = keep.back() = true;
    simplify(stations, 0, stations.size() - 1, 0.5f * out.width, keep);
    for (std::size_t i = 0; i < stations.size(); ++i)
        if (keep[i]) out.points.push_back(stations[i]);
    for (std::size_t i = 0; i + 1 < out.points.size(); ++i)
        out.length += glm::length(out.points[i + 1] - out.points[i]);
    for (const glm::vec3& p : points)
        out.error = std::max(out.error, distance_to_polyline(p, out.points));
    return out;
}

float elongation(const element_spine& spine) {
    if (spine.points.empty()) return 0.0f;
    return spine.width > 0.0f ? spine.length / spine.width : std::numeric_limits<float>::infinity();
}

element_lines build_element_lines(const mesh_data& mesh, std::span<const std::uint32_t> triangles,
                                  std::span<const triangle_coverage> coverage) {
    element_lines out;
    const element_spine spine = extract_spine(mesh, triangles);
    if (spine.points.size() < 2) return out;
    out.length = spine.length;
    out.error = spine.error;

    glm::vec3 normal_sum{0.0f};
    float magnitude_sum = 0.0f;
    std::vector<vertex> opaque;  // opaque cell centres: where a line may read its colour
    std::vector<vertex> element_vertices;  // for Luft 2007's normals below
    bool implicit = false;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        triangle_corners corners;
        for (std::size_t k = 0; k < 3; ++k) {
            corners.v[k] = mesh.vertices[mesh.indices[std::size_t(triangles[i]) * 3 + k]];
            element_vertices.push_back(corners.v[k]);
            implicit = implicit || carries_ambient(corners.v[k]);
        }
        const glm::vec3 n = glm::cross(corners.v[1].position - corners.v[0].position,
                                       corners.v[2].position - corners.v[0].position);
        normal_sum += n;
        magnitude_sum += glm::length(n);
        for (std::uint64_t bits = coverage[i].opaque_cells; bits != 0; bits &= bits - 1)
            opaque.push_back(point_at(corners, coverage_cell_centre(std::countr_zero(bits))));
    }
    const glm::vec3 surface = glm::length(normal_sum) >= k_surface_normal_agreement * magnitude_sum
                                  ? glm::normalize(normal_sum)
                                  : glm::vec3{0.0f};
    for (std::size_t i = 0; i + 1 < spine.points.size(); ++i) {
        const glm::vec3 a = spine.points[i];
        const glm::vec3 b = spine.points[i + 1];
        const glm::vec3 direction = glm::normalize(b - a);
        const glm::vec3 middle = 0.5f * (a + b);
        const glm::vec2 uv = opaque.empty() ? glm::vec2{0.0f} : nearest_vertex(opaque, middle).uv;
        const glm::vec3 n = line_normal(direction, surface);
        out.vertices.push_back({a, implicit ? nearest_vertex(element_vertices, a).normal : n, uv});
        out.vertices.push_back({b, implicit ? nearest_vertex(element_vertices, b).normal : n, uv});
    }
    return out;
}

}  // namespace sylva
