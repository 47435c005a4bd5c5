#include "lod/eco_tiles.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <numeric>
#include <stdexcept>

#include "components/tile.h"
#include "components/tile_visibility.h"

namespace sylva {
namespace {

// Quadrant of a point in a square split at `center`: bit 0 = +x half, bit 1 = +z half.
std::uint32_t quadrant(glm::dvec2 p, glm::dvec2 center) {
    return (p.x >= center.x ? 1u : 0u) | (p.y >= center.y ? 2u : 0u);
}

class subdivider {
public:
    subdivider(std::span<const glm::dvec2> xz, std::uint32_t max_per_tile, eco_tile_tree& tree)
        : m_xz(xz), m_max(max_per_tile), m_tree(tree), m_scratch(xz.size()) {}

    // Deussen 2002 §6.2: split a tile into four sub-tiles while it holds too many instances.
    std::uint32_t build(glm::dvec2 min, double size, std::uint32_t parent, std::uint16_t depth,
                        std::uint32_t begin, std::uint32_t end) {
        const auto index = static_cast<std::uint32_t>(m_tree.nodes.size());
        eco_tile_node node;
        node.min = min;
        node.size = size;
        node.parent = parent;
        node.depth = depth;
        node.first_plant = begin;
        node.plant_count = end - begin;
        m_tree.nodes.push_back(node);
        if (end - begin <= m_max || depth >= k_max_eco_tile_depth) return index;
        const double half = 0.5 * size;
        const std::array<std::uint32_t, 5> bounds = partition(begin, end, min + glm::dvec2(half));
        for (std::uint32_t q = 0; q < 4; ++q) {
            const glm::dvec2 child_min =
                min + glm::dvec2((q & 1u) ? half : 0.0, (q & 2u) ? half : 0.0);
            const std::uint32_t child =
                build(child_min, half, index, std::uint16_t(depth + 1), bounds[q], bounds[q + 1]);
            m_tree.nodes[index].children[q] = child;
        }
        return index;
    }

private:
    // Stable counting sort of order[begin, end) by quadrant; returns the quadrant boundaries.
    std::array<std::uint32_t, 5> partition(std::uint32_t begin, std::uint32_t end,
                                           glm::dvec2 center) {
        auto& order = m_tree.order;
        std::array<std::uint32_t, 5> bounds{};
        for (std::uint32_t i = begin; i < end; ++i) ++bounds[quadrant(m_xz[order[i]], center) + 1];
        bounds[0] = begin;
        for (std::size_t q = 1; q < 5; ++q) bounds[q] += bounds[q - 1];
        std::array<std::uint32_t, 4> next{bounds[0], bounds[1], bounds[2], bounds[3]};
        for (std::uint32_t i = begin; i < end; ++i)
            m_scratch[next[quadrant(m_xz[order[i]], center)]++] = order[i];
        std::copy(m_scratch.begin() + begin, m_scratch.begin() + end, order.begin() + begin);
        return bounds;
    }

    std::span<const glm::dvec2> m_xz;
    std::uint32_t m_max;
    eco_tile_tree& m_tree;
    std::vector<std::uint32_t> m_scratch;
};

struct height_range {
    float lo = 0.0f;
    float hi = 0.0f;
};

// Range of the terrain's grid samples over the cells the square touches: the bilinear surface
// never leaves the range of its cell corners, so this bounds the ground under the square.
height_range terrain_range(const heightfield& terrain, glm::dvec2 min, double size) {
    if (terrain.resolution < 2) return {};
    const double half = 0.5 * terrain.size_m;
    const double spacing = terrain.spacing();
    const double last = double(terrain.resolution - 1);
    const auto grid = [&](double world, bool up) {
        const double g = (world + half) / spacing;
        return static_cast<std::uint32_t>(std::clamp(up ? std::ceil(g) : std::floor(g), 0.0, last));
    };
    const std::uint32_t c0 = grid(min.x, false), c1 = grid(min.x + size, true);
    const std::uint32_t r0 = grid(min.y, false), r1 = grid(min.y + size, true);
    height_range range{std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest()};
    for (std::uint32_t r = r0; r <= r1; ++r) {
        for (std::uint32_t c = c0; c <= c1; ++c) {
            range.lo = std::min(range.lo, terrain.at(c, r));
            range.hi = std::max(range.hi, terrain.at(c, r));
        }
    }
    return range;
}

}  // namespace

eco_tile_tree build_eco_tiles(std::span<const glm::dvec2> plant_xz, std::array<double, 4> area,
                              std::uint32_t max_plants_per_tile) {
    if (max_plants_per_tile == 0)
        throw std::invalid_argument("build_eco_tiles: max_plants_per_tile must be >= 1");
    if (!(area[0] < area[2]) || !(area[1] < area[3]))
        throw std::invalid_argument("build_eco_tiles: area must have x0 < x1 and z0 < z1");
    if (plant_xz.size() >= k_no_eco_tile)
        throw std::invalid_argument("build_eco_tiles: too many plants");
    glm::dvec2 lo{area[0], area[1]};
    glm::dvec2 hi{area[2], area[3]};
    for (const glm::dvec2 p : plant_xz) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double size = std::max(hi.x - lo.x, hi.y - lo.y);
    eco_tile_tree tree;
    tree.order.resize(plant_xz.size());
    std::iota(tree.order.begin(), tree.order.end(), 0u);
    subdivider(plant_xz, max_plants_per_tile, tree)
        .build(lo, size, k_no_eco_tile, 0, 0, static_cast<std::uint32_t>(plant_xz.size()));
    return tree;
}

std::vector<ecs::entity> create_tile_entities(ecs::world& world, const eco_tile_tree& tree,
                                              const heightfield& terrain,
                                              const eco_tile_extent& extent) {
    // Heights bottom-up: leaves scan the grid once between them, parents merge their children
    // (children follow their parent in preorder, so a reverse walk sees them first).
    std::vector<height_range> heights(tree.nodes.size());
    for (std::size_t i = tree.nodes.size(); i-- > 0;) {
        const eco_tile_node& n = tree.nodes[i];
        if (n.is_leaf()) {
            heights[i] = terrain_range(terrain, n.min, n.size);
            continue;
        }
        heights[i] = heights[n.children[0]];
        for (const std::uint32_t c : n.children) {
            heights[i].lo = std::min(heights[i].lo, heights[c].lo);
            heights[i].hi = std::max(heights[i].hi, heights[c].hi);
        }
    }
    std::vector<ecs::entity> entities(tree.nodes.size());
    for (auto& e : entities) e = world.create();
    const auto handle = [&](std::uint32_t node) {
        return node == k_no_eco_tile ? ecs::entity{} : entities[node];
    };
    const glm::dvec2 offset_xz{extent.world_offset.x, extent.world_offset.z};
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        const eco_tile_node& n = tree.nodes[i];
        tile t;
        t.min = n.min + offset_xz;
        t.size = n.size;
        t.min_height = float(double(heights[i].lo) + extent.world_offset.y);
        t.max_height = float(double(heights[i].hi) + extent.world_offset.y);
        t.reach_m = extent.reach_m;
        t.max_scale = extent.max_scale;
        t.parent = handle(n.parent);
        for (std::size_t q = 0; q < 4; ++q) t.children[q] = handle(n.children[q]);
        t.first_plant = n.first_plant;
        t.plant_count = n.plant_count;
        t.depth = n.depth;
        world.emplace<tile>(entities[i], t);
        world.emplace<tile_visibility>(entities[i]);
    }
    world.align<tile, tile_visibility>();
    return entities;
}

}  // namespace sylva
