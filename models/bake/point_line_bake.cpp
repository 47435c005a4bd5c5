#include "models/bake/point_line_bake.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include "models/bake/colour_importance.h"
#include "models/bake/line_extraction.h"
#include "models/bake/point_sampling.h"
#include "models/random.h"

namespace sylva {
namespace {

constexpr std::uint8_t k_twig_level = 2;  // W&P stem levels from here on are twigs
constexpr int k_max_octree_depth = 3;
// Independent random streams: hash_combine(seed, stream, part index).
constexpr std::uint64_t k_triangle_order_stream = 1;
constexpr std::uint64_t k_point_stream = 2;
constexpr std::uint64_t k_line_order_stream = 3;

// What separates parts besides primitive and material: petals (and anything else important)
// are reduced more slowly than the rest of the foliage (§4.3), so they are parts of their own.
enum class kind_class : std::uint8_t { bark, foliage, important };

struct source_triangle {
    std::uint32_t index = 0;  // in lods[0]
    material_kind material = material_kind::leaf;
    part_kind kind = part_kind::leaf;
    std::uint8_t level = 0;
    std::uint32_t branch = 0;
    triangle_coverage coverage;
    std::uint32_t element = 0;
    std::uint32_t cell = 0;
    lod_primitive primitive = lod_primitive::points;
    kind_class group = kind_class::foliage;
};

struct bake_context {
    const plant_model& model;
    const mesh_data& mesh;
    const point_line_settings& settings;
    bool has_parts = false;
    std::vector<source_triangle> triangles;
    glm::vec3 majority_colour{0.0f};  // of the plant's elements (colour_importance.h)
};

struct part_plan {
    std::uint32_t cell = 0;
    lod_primitive primitive = lod_primitive::points;
    material_kind material = material_kind::leaf;
    kind_class group = kind_class::foliage;
    std::vector<std::uint32_t> slots;  // into bake_context::triangles
    double area = 0.0;
};

bool is_bark_material(material_kind m) {
    return m == material_kind::bark || m == material_kind::ground;
}

triangle_corners corners_of(const mesh_data& mesh, std::uint32_t triangle) {
    triangle_corners c;
    for (std::size_t k = 0; k < 3; ++k)
        c.v[k] = mesh.vertices[mesh.indices[std::size_t(triangle) * 3 + k]];
    return c;
}

surface_texture surface_for(const bake_context& ctx, material_kind material) {
    return surface_of(material, ctx.model.leaf_texture, ctx.model.bark_texture);
}

// Every triangle in a submesh, measured; those without opaque area dropped.
void gather_triangles(bake_context& ctx) {
    const mesh_data& mesh = ctx.mesh;
    std::vector<bool> taken(mesh.triangle_count(), false);
    for (const submesh& sub : mesh.submeshes) {
        if (sub.first_index % 3 != 0 || sub.index_count % 3 != 0 ||
            std::size_t(sub.first_index) + sub.index_count > mesh.indices.size())
            throw std::invalid_argument("bake_point_lines: submesh outside the index array");
        for (std::uint32_t t = sub.first_index / 3; t < (sub.first_index + sub.index_count) / 3;
             ++t) {
            if (taken[t]) continue;
            taken[t] = true;
            for (std::size_t k = 0; k < 3; ++k)
                if (mesh.indices[std::size_t(t) * 3 + k] >= mesh.vertices.size())
                    throw std::invalid_argument(
                        "bake_point_lines: index out of range in triangle " + std::to_string(t));
            source_triangle s;
            s.index = t;
            s.material = sub.material;
            s.coverage = measure_coverage(corners_of(mesh, t), surface_for(ctx, sub.material));
            if (!std::isfinite(s.coverage.opaque_area) || !(s.coverage.opaque_area > 0.0f))
                continue;
            if (ctx.has_parts) {
                const triangle_part& p = mesh.parts[t];
                s.kind = p.kind;
                s.level = p.level;
                s.branch = p.branch;
            } else {
                s.kind = is_bark_material(sub.material) ? part_kind::bark : part_kind::leaf;
            }
            ctx.triangles.push_back(s);
        }
    }
}

glm::vec3 mean_colour(const bake_context& ctx, std::span<const std::uint32_t> slots) {
    glm::dvec3 sum{0.0};
    double area = 0.0;
    for (const std::uint32_t s : slots) {
        const triangle_coverage& c = ctx.triangles[s].coverage;
        sum += double(c.opaque_area) * glm::dvec3(c.colour);
        area += c.opaque_area;
    }
    return area > 0.0 ? glm::vec3(sum / area) : glm::vec3{0.0f};
}

// The box around every triangle's corners.
std::pair<glm::vec3, glm::vec3> triangle_bounds(const bake_context& ctx) {
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{std::numeric_limits<float>::lowest()};
    for (const source_triangle& s : ctx.triangles)
        for (const vertex& v : corners_of(ctx.mesh, s.index).v) {
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
        }
    return {lo, hi};
}

float plant_size(const bake_context& ctx) {
    const auto [lo, hi] = triangle_bounds(ctx);
    const glm::vec3 extent = hi - lo;
    return std::max({extent.x, extent.y, extent.z, 0.0f});
}

// Deussen 2002 §4.2: "thin and long structures like twigs or several types of leaves are better
// represented by a line". The paper's user marks them; we decide from kind and shape (see
// point_line_bake.h).
lod_primitive choose_primitive(const bake_context& ctx, const source_triangle& first,
                               const element_spine& spine, float size) {
    if (first.kind == part_kind::needle || first.kind == part_kind::blade)
        return lod_primitive::lines;
    const bool long_and_thin = elongation(spine) >= ctx.settings.line_elongation;
    if (first.kind == part_kind::bark) {
        const bool twig = (ctx.has_parts && first.level >= k_twig_level) ||
                          spine.thickness <= k_thin_stem_fraction * size;
        return long_and_thin && twig ? lod_primitive::lines : lod_primitive::points;
    }
    return !ctx.has_parts && long_and_thin ? lod_primitive::lines : lod_primitive::points;
}

// Connected elements, then per element its primitive and class. An imported model knows no
// petals, so with automatic importance a foliage element whose colour stands out from the
// plant's (Deussen 2002 §4.3, future work) is classed as one.
void classify_elements(bake_context& ctx) {
    std::vector<std::uint32_t> triangle_index(ctx.triangles.size());
    std::vector<std::uint64_t> group(ctx.triangles.size());
    for (std::size_t i = 0; i < ctx.triangles.size(); ++i) {
        const source_triangle& s = ctx.triangles[i];
        triangle_index[i] = s.index;
        group[i] =
            std::uint64_t(s.material) | std::uint64_t(s.kind) << 8 | std::uint64_t(s.branch) << 16;
    }
    const std::vector<std::uint32_t> element = connected_elements(ctx.mesh, triangle_index, group);
    const std::uint32_t element_count =
        element.empty() ? 0 : *std::max_element(element.begin(), element.end()) + 1;
    std::vector<std::vector<std::uint32_t>> slots(element_count);
    for (std::uint32_t i = 0; i < element.size(); ++i) {
        ctx.triangles[i].element = element[i];
        slots[element[i]].push_back(i);
    }
    std::vector<glm::vec3> colours(element_count);
    std::vector<float> areas(element_count, 0.0f);
    for (std::uint32_t e = 0; e < element_count; ++e) {
        colours[e] = mean_colour(ctx, slots[e]);
        for (const std::uint32_t s : slots[e]) areas[e] += ctx.triangles[s].coverage.opaque_area;
    }
    ctx.majority_colour = majority_colour(colours, areas);
    const float size = plant_size(ctx);
    const float petal_difference = 0.5f * (k_distinct_low + k_distinct_high);
    for (std::uint32_t e = 0; e < element_count; ++e) {
        const std::vector<std::uint32_t>& members = slots[e];
        source_triangle& first = ctx.triangles[members.front()];
        element_spine spine;
        if (first.kind == part_kind::bark || !ctx.has_parts) {
            std::vector<std::uint32_t> triangles;
            for (const std::uint32_t s : members) triangles.push_back(ctx.triangles[s].index);
            spine = extract_spine(ctx.mesh, triangles);
        }
        const lod_primitive primitive = choose_primitive(ctx, first, spine, size);
        part_kind kind = first.kind;
        if (!ctx.has_parts && ctx.settings.automatic_importance && kind == part_kind::leaf &&
            colour_difference(colours[e], ctx.majority_colour) >= petal_difference)
            kind = part_kind::petal;
        const kind_class group_of = kind == part_kind::bark    ? kind_class::bark
                                    : kind == part_kind::petal ? kind_class::important
                                                               : kind_class::foliage;
        for (const std::uint32_t s : members) {
            ctx.triangles[s].primitive = primitive;
            ctx.triangles[s].kind = kind;
            ctx.triangles[s].group = group_of;
        }
    }
}

// Deussen 2002 §6.1: "large and complex objects are spatially subdivided by an octree of small
// depth"; each triangle goes to the cell holding its centroid, empty cells are dropped, and a
// cell's bounds are its triangles' (they may overlap a neighbour's).
std::vector<lod_cell> assign_cells(bake_context& ctx) {
    const auto per_axis = std::uint32_t(1) << ctx.settings.octree_depth;
    const auto [lo, hi] = triangle_bounds(ctx);
    const glm::vec3 extent = glm::max(hi - lo, glm::vec3{1e-20f});
    std::map<std::uint32_t, std::uint32_t> compact;  // grid cell -> cell index, in grid order
    std::vector<std::uint32_t> grid_cell(ctx.triangles.size());
    for (std::size_t i = 0; i < ctx.triangles.size(); ++i) {
        const triangle_corners c = corners_of(ctx.mesh, ctx.triangles[i].index);
        const glm::vec3 centroid = (c.v[0].position + c.v[1].position + c.v[2].position) / 3.0f;
        std::uint32_t cell = 0;
        for (int axis = 0; axis < 3; ++axis) {
            const float at = (centroid[axis] - lo[axis]) / extent[axis] * float(per_axis);
            cell = cell * per_axis + std::min(std::uint32_t(std::max(at, 0.0f)), per_axis - 1);
        }
        grid_cell[i] = cell;
        compact.emplace(cell, 0u);
    }
    std::uint32_t next = 0;
    for (auto& entry : compact) entry.second = next++;
    std::vector<lod_cell> cells(compact.size());
    std::vector<bool> seen(cells.size(), false);
    for (std::size_t i = 0; i < ctx.triangles.size(); ++i) {
        const std::uint32_t cell = compact[grid_cell[i]];
        ctx.triangles[i].cell = cell;
        for (const vertex& v : corners_of(ctx.mesh, ctx.triangles[i].index).v) {
            cells[cell].bounds_min =
                seen[cell] ? glm::min(cells[cell].bounds_min, v.position) : v.position;
            cells[cell].bounds_max =
                seen[cell] ? glm::max(cells[cell].bounds_max, v.position) : v.position;
            seen[cell] = true;
        }
    }
    return cells;
}

// At most k_max_cell_parts per cell: merge the two smallest parts that share a material (so the
// merged part still draws with one), preferring two of the same primitive. The merged part keeps
// the primitive and class of the bigger one.
void merge_excess_parts(std::vector<part_plan>& parts) {
    while (parts.size() > k_max_cell_parts) {
        std::size_t best_a = parts.size();
        std::size_t best_b = parts.size();
        std::pair<bool, double> best_score{true, std::numeric_limits<double>::infinity()};
        for (std::size_t a = 0; a < parts.size(); ++a)
            for (std::size_t b = a + 1; b < parts.size(); ++b) {
                if (parts[a].material != parts[b].material) continue;
                const std::pair<bool, double> score{parts[a].primitive != parts[b].primitive,
                                                    parts[a].area + parts[b].area};
                if (score < best_score) {
                    best_score = score;
                    best_a = a;
                    best_b = b;
                }
            }
        if (best_a == parts.size())
            throw std::logic_error("bake_point_lines: more parts than materials allow");
        if (parts[best_b].area > parts[best_a].area) std::swap(parts[best_a], parts[best_b]);
        part_plan& keep = parts[best_a];
        keep.slots.insert(keep.slots.end(), parts[best_b].slots.begin(), parts[best_b].slots.end());
        std::sort(keep.slots.begin(), keep.slots.end());
        keep.area += parts[best_b].area;
        parts.erase(parts.begin() + std::ptrdiff_t(best_b));
    }
}

// Parts by (cell, class, primitive, material), cells in order.
std::vector<std::vector<part_plan>> plan_parts(const bake_context& ctx, std::size_t cell_count) {
    std::vector<std::map<std::uint32_t, part_plan>> keyed(cell_count);
    for (std::uint32_t i = 0; i < ctx.triangles.size(); ++i) {
        const source_triangle& s = ctx.triangles[i];
        const std::uint32_t key = std::uint32_t(s.group) << 16 | std::uint32_t(s.primitive) << 8 |
                                  std::uint32_t(s.material);
        part_plan& plan = keyed[s.cell][key];
        plan.cell = s.cell;
        plan.primitive = s.primitive;
        plan.material = s.material;
        plan.group = s.group;
        plan.slots.push_back(i);
        plan.area += s.coverage.opaque_area;
    }
    std::vector<std::vector<part_plan>> cells(cell_count);
    for (std::size_t c = 0; c < cell_count; ++c) {
        for (auto& entry : keyed[c]) cells[c].push_back(std::move(entry.second));
        merge_excess_parts(cells[c]);
    }
    return cells;
}

// Points in the reverse of the triangle order, grouped by triangle (point_line_model.h).
void sample_points(const bake_context& ctx, std::span<const std::uint32_t> order,
                   std::uint32_t part_index, lod_part& part, point_line_model& out) {
    const std::size_t n = order.size();
    std::vector<float> areas(n);
    for (std::size_t i = 0; i < n; ++i) areas[i] = ctx.triangles[order[i]].coverage.opaque_area;
    rng random(hash_combine(ctx.settings.seed, k_point_stream, part_index));
    part.stratified = similar_areas(areas, ctx.settings.similar_area_ratio);
    const std::vector<std::uint32_t> counts =
        part.stratified ? std::vector<std::uint32_t>(n, 2u) : area_weighted_counts(areas, random);
    const surface_texture surface = surface_for(ctx, part.material);
    part.first_point = std::uint32_t(out.points.size());
    part.first_after = std::uint32_t(out.points_after.size());
    out.points_after.resize(out.points_after.size() + n + 1, 0u);
    std::uint32_t* after = &out.points_after[part.first_after];
    for (std::size_t t = n; t-- > 0;) {
        const source_triangle& s = ctx.triangles[order[t]];
        const triangle_corners corners = corners_of(ctx.mesh, s.index);
        if (part.stratified) {
            for (const barycentric_region& half : triangle_halves(corners))
                out.points.push_back(
                    sample_opaque_point(corners, s.coverage, surface, half, random));
        } else {
            for (std::uint32_t k = 0; k < counts[t]; ++k)
                out.points.push_back(sample_opaque_point(corners, s.coverage, surface, {}, random));
        }
        after[t] = after[t + 1] + counts[t];
    }
    part.point_count = after[0];
}

// Deussen 2002 §4.2: lines per element (within this part's cell), l and ε_l over them, and the
// "line set is also randomly reordered".
void extract_lines(const bake_context& ctx, std::span<const std::uint32_t> slots,
                   std::uint32_t part_index, lod_part& part, point_line_model& out) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> by_element;  // (element, slot)
    for (const std::uint32_t s : slots) by_element.emplace_back(ctx.triangles[s].element, s);
    std::sort(by_element.begin(), by_element.end());
    std::vector<std::array<vertex, 2>> lines;
    for (std::size_t begin = 0; begin < by_element.size();) {
        std::size_t end = begin;
        std::vector<std::uint32_t> triangles;
        std::vector<triangle_coverage> coverage;
        for (; end < by_element.size() && by_element[end].first == by_element[begin].first; ++end) {
            triangles.push_back(ctx.triangles[by_element[end].second].index);
            coverage.push_back(ctx.triangles[by_element[end].second].coverage);
        }
        const element_lines element = build_element_lines(ctx.mesh, triangles, coverage);
        for (std::size_t v = 0; v + 1 < element.vertices.size(); v += 2)
            lines.push_back({element.vertices[v], element.vertices[v + 1]});
        part.line_length_m += element.length;
        part.line_error_m = std::max(part.line_error_m, element.error);
        begin = end;
    }
    rng random(hash_combine(ctx.settings.seed, k_line_order_stream, part_index));
    shuffle_groups(lines, 1, random);
    part.first_line = std::uint32_t(out.lines.size() / 2);
    part.line_count = std::uint32_t(lines.size());
    for (const std::array<vertex, 2>& line : lines)
        out.lines.insert(out.lines.end(), line.begin(), line.end());
}

part_kind majority_kind(const bake_context& ctx, std::span<const std::uint32_t> slots) {
    std::array<double, 6> area{};
    for (const std::uint32_t s : slots)
        area[std::size_t(ctx.triangles[s].kind)] += ctx.triangles[s].coverage.opaque_area;
    return part_kind(std::max_element(area.begin(), area.end()) - area.begin());
}

// One part: its triangles shuffled into the output mesh, then its points or lines. Returns its
// mean colour for the importance.
glm::vec3 bake_part(const bake_context& ctx, part_plan plan, point_line_model& out) {
    const auto part_index = std::uint32_t(out.parts.size());
    lod_part part;
    part.primitive = plan.primitive;
    part.material = plan.material;
    part.kind = majority_kind(ctx, plan.slots);
    // Deussen 2002 §4.1: "the triangles and points are randomly reordered".
    rng random(hash_combine(ctx.settings.seed, k_triangle_order_stream, part_index));
    shuffle_groups(plan.slots, 1, random);

    mesh_data& mesh = out.triangles;
    part.first_index = std::uint32_t(mesh.indices.size());
    part.triangle_count = std::uint32_t(plan.slots.size());
    glm::dvec3 weighted_centre{0.0};
    double area = 0.0;
    for (const std::uint32_t s : plan.slots) {
        const source_triangle& t = ctx.triangles[s];
        for (std::size_t k = 0; k < 3; ++k)
            mesh.indices.push_back(ctx.mesh.indices[std::size_t(t.index) * 3 + k]);
        if (ctx.has_parts) mesh.parts.push_back(ctx.mesh.parts[t.index]);
        weighted_centre += double(t.coverage.opaque_area) * glm::dvec3(t.coverage.opaque_centroid);
        area += t.coverage.opaque_area;
    }
    mesh.submeshes.push_back({part.first_index, 3 * part.triangle_count, part.material});
    part.area_m2 = float(area);
    part.center = glm::vec3(weighted_centre / area);

    if (part.primitive == lod_primitive::points)
        sample_points(ctx, plan.slots, part_index, part, out);
    else
        extract_lines(ctx, plan.slots, part_index, part, out);
    out.parts.push_back(part);
    return mean_colour(ctx, plan.slots);
}

// Deussen 2002 §4.3 (future work: colour analysis); see models/bake/colour_importance.h.
void assign_importance(const bake_context& ctx, std::span<const glm::vec3> colours,
                       point_line_model& out) {
    for (std::size_t i = 0; i < out.parts.size(); ++i) {
        lod_part& part = out.parts[i];
        part.importance =
            ctx.settings.automatic_importance
                ? colour_importance(colour_difference(colours[i], ctx.majority_colour),
                                    ctx.settings.petal_importance)
                : 1.0f;
        if (part.kind == part_kind::petal)
            part.importance = std::max(part.importance, ctx.settings.petal_importance);
    }
}

}  // namespace

point_line_model bake_point_lines(const plant_model& model, const point_line_settings& settings) {
    if (settings.octree_depth < 0 || settings.octree_depth > k_max_octree_depth)
        throw std::invalid_argument("bake_point_lines: octree_depth " +
                                    std::to_string(settings.octree_depth) + " outside 0.." +
                                    std::to_string(k_max_octree_depth));
    const mesh_data& mesh = model.lods[0];
    if (!mesh.parts.empty() && mesh.parts.size() != mesh.triangle_count())
        throw std::invalid_argument("bake_point_lines: parts do not match the triangles");
    bake_context ctx{model, mesh, settings, !mesh.parts.empty(), {}, {}};
    gather_triangles(ctx);
    point_line_model out;
    out.triangles.vertices = mesh.vertices;
    if (ctx.triangles.empty()) return out;
    classify_elements(ctx);
    out.cells = assign_cells(ctx);
    out.triangles.bounds_min = out.cells.front().bounds_min;
    out.triangles.bounds_max = out.cells.front().bounds_max;
    std::vector<glm::vec3> colours;
    std::vector<std::vector<part_plan>> plans = plan_parts(ctx, out.cells.size());
    for (std::size_t c = 0; c < out.cells.size(); ++c) {
        lod_cell& cell = out.cells[c];
        out.triangles.bounds_min = glm::min(out.triangles.bounds_min, cell.bounds_min);
        out.triangles.bounds_max = glm::max(out.triangles.bounds_max, cell.bounds_max);
        cell.first_part = std::uint32_t(out.parts.size());
        cell.part_count = std::uint32_t(plans[c].size());
        for (part_plan& plan : plans[c]) colours.push_back(bake_part(ctx, std::move(plan), out));
    }
    assign_importance(ctx, colours, out);
    return out;
}

}  // namespace sylva
