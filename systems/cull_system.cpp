#include "systems/cull_system.h"

#include <algorithm>
#include <array>
#include <limits>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

#include "ecs/parallel.h"
#include "lod/eco_tiles.h"

namespace sylva {

frustum_planes extract_frustum_planes(const glm::mat4& m) {
    frustum_planes f;
    const glm::vec4 row0{m[0][0], m[1][0], m[2][0], m[3][0]};
    const glm::vec4 row1{m[0][1], m[1][1], m[2][1], m[3][1]};
    const glm::vec4 row2{m[0][2], m[1][2], m[2][2], m[3][2]};
    const glm::vec4 row3{m[0][3], m[1][3], m[2][3], m[3][3]};
    f.planes[0] = row3 + row0;  // left
    f.planes[1] = row3 - row0;  // right
    f.planes[2] = row3 + row1;  // bottom
    f.planes[3] = row3 - row1;  // top
    f.planes[4] = row3 + row2;  // near
    f.planes[5] = row3 - row2;  // far
    for (auto& p : f.planes) p /= glm::length(glm::vec3(p));
    return f;
}

bool sphere_in_frustum(const frustum_planes& f, glm::vec3 center, float radius) {
    for (const auto& p : f.planes)
        if (glm::dot(glm::vec3(p), center) + p.w < -radius) return false;
    return true;
}

bool box_in_frustum(const frustum_planes& f, glm::vec3 lo, glm::vec3 hi) {
    for (const auto& p : f.planes) {
        // The box corner farthest along the plane normal (the "p-vertex").
        const glm::vec3 far_corner{p.x >= 0.0f ? hi.x : lo.x, p.y >= 0.0f ? hi.y : lo.y,
                                   p.z >= 0.0f ? hi.z : lo.z};
        if (glm::dot(glm::vec3(p), far_corner) + p.w < 0.0f) return false;
    }
    return true;
}

namespace {

using plant_query =
    ecs::query<const world_transform, const bounds, const plant_instance, lod_state>;

struct cull_view {
    const camera* cam;
    frustum_planes frustum;
    const std::vector<species_entry>* library;
    float shadow_distance;
    float max_species_distance;  // the largest max_distance_m of any species
    // Points and lines draw every plant up to the far plane: Eq. 1 makes a plant's cost fall
    // with the square of its distance and far eco tiles draw their aggregated sets (Deussen
    // 2002 §6.2), so the species' draw distances (a mesh-level budget) do not apply. The same
    // holds for ladders that end on the eco-tile rung.
    bool unlimited_distance;
};

void cull_plants(const cull_view& view, const plant_query& plants, std::size_t begin,
                 std::size_t end) {
    const camera& cam = *view.cam;
    plants.each_chunk(
        begin, end,
        [&](ecs::entity, const world_transform& t, const bounds& b, const plant_instance& p,
            lod_state& lod) {
            // Camera-relative in double, then float: exact to millimetres anywhere on Earth.
            const glm::vec3 base{t.position - cam.position};
            const glm::vec3 center = base + glm::vec3(0.0f, b.center_height, 0.0f);
            const float distance = glm::length(center) - b.radius;
            const auto& species = (*view.library)[static_cast<std::size_t>(p.species)];
            const float max_distance = view.unlimited_distance ? std::numeric_limits<float>::infinity()
                                                               : species.max_distance_m * t.scale * cam.lod_scale;
            const bool near_enough = distance < max_distance;
            lod.visible = near_enough && sphere_in_frustum(view.frustum, center, b.radius) ? 1 : 0;
            lod.in_shadow_range = near_enough && distance < view.shadow_distance ? 1 : 0;
        });
}

void hide_plants(const plant_query& plants, std::size_t begin, std::size_t end) {
    plants.each_chunk(begin, end,
                      [](ecs::entity, const world_transform&, const bounds&, const plant_instance&,
                         lod_state& lod) {
                          lod.visible = 0;
                          lod.in_shadow_range = 0;
                      });
}

// A tile's verdict from its box: the square and the terrain range grown by the plants' reach,
// which holds every plant's bounding sphere. The box's distance is a lower bound of every
// plant's sphere distance, so a tile beyond max draw distance * max scale holds no plant that
// flat culling would keep, and likewise for the frustum and the shadow distance.
tile_visibility classify_tile(const cull_view& view, const tile& t) {
    const camera& cam = *view.cam;
    const double r = t.reach_m;
    const glm::vec3 lo{glm::dvec3(t.min.x - r, double(t.min_height) - r, t.min.y - r) -
                       cam.position};
    const glm::vec3 hi{
        glm::dvec3(t.min.x + t.size + r, double(t.max_height) + r, t.min.y + t.size + r) -
        cam.position};
    const float distance = glm::length(glm::max(glm::max(lo, -hi), glm::vec3(0.0f)));
    const bool near_enough =
        view.unlimited_distance || distance < view.max_species_distance * t.max_scale * cam.lod_scale;
    tile_visibility v;
    v.visible = near_enough && box_in_frustum(view.frustum, lo, hi) ? 1 : 0;
    v.in_shadow_range = near_enough && distance < view.shadow_distance ? 1 : 0;
    return v;
}

// Depth-first from every root; a culled tile's subtree is marked culled without box tests. The
// stack is fixed (no allocation): depth-first over 4-way nodes needs at most 3 per level + 4.
// Returns the end of the plant range the tiles cover.
std::size_t walk_tiles(const cull_view& view, const ecs::component_table<tile>& tiles,
                       ecs::component_table<tile_visibility>& visibility) {
    struct pending {
        ecs::entity e;
        bool parent_culled;
    };
    std::array<pending, 3 * (k_max_eco_tile_depth + 1) + 4> stack;
    std::size_t covered = 0;
    const auto roots = tiles.entities();
    for (std::size_t i = 0; i < roots.size(); ++i) {
        if (!tiles.data()[i].parent.is_null()) continue;
        covered = std::max(covered,
                           std::size_t(tiles.data()[i].first_plant) + tiles.data()[i].plant_count);
        std::size_t top = 0;
        stack[top++] = {roots[i], false};
        while (top > 0) {
            const pending next = stack[--top];
            const tile& t = tiles.get(next.e);
            tile_visibility& v = visibility.get(next.e);
            v = next.parent_culled ? tile_visibility{} : classify_tile(view, t);
            const bool culled = v.visible == 0 && v.in_shadow_range == 0;
            for (std::size_t q = 4; q-- > 0;) {
                if (t.children[q].is_null()) continue;
                if (top == stack.size())
                    throw std::logic_error("cull: eco tiles deeper than k_max_eco_tile_depth");
                stack[top++] = {t.children[q], culled};
            }
        }
    }
    return covered;
}

// The cheap check of the precondition: a leaf's first plant stands on the leaf's square.
void expect_plant_in_tile(const plant_query& plants, const tile& t) {
    constexpr double k_tolerance_m = 1e-3;
    const glm::dvec3 p = plants.column<const world_transform>()[t.first_plant].position;
    if (p.x < t.min.x - k_tolerance_m || p.x > t.min.x + t.size + k_tolerance_m ||
        p.z < t.min.y - k_tolerance_m || p.z > t.min.y + t.size + k_tolerance_m)
        throw std::logic_error(
            "cull: plant " + std::to_string(t.first_plant) +
            " is not on its eco tile; plants must be created in eco_tile_tree::order");
}

void cull_tiled(const ecs::system_context<cull_system>& ctx, const cull_view& view,
                const plant_query& plants, const ecs::component_table<tile>& tiles,
                const ecs::component_table<tile_visibility>& visibility, std::size_t covered) {
    if (covered > plants.size())
        throw std::logic_error("cull: eco tiles cover " + std::to_string(covered) +
                               " plants but there are " + std::to_string(plants.size()));
    ctx.parallel_for(tiles.size(), k_cull_tile_chunk,
                     [&](std::size_t begin, std::size_t end, std::size_t) {
                         for (std::size_t i = begin; i < end; ++i) {
                             const tile& t = tiles.data()[i];
                             if (!t.is_leaf() || t.plant_count == 0) continue;
                             const tile_visibility& v = visibility.get(tiles.entities()[i]);
                             const std::size_t first = t.first_plant;
                             if (v.visible == 0 && v.in_shadow_range == 0) {
                                 hide_plants(plants, first, first + t.plant_count);
                             } else {
                                 expect_plant_in_tile(plants, t);
                                 cull_plants(view, plants, first, first + t.plant_count);
                             }
                         }
                     });
    // Plants the tiles do not cover (spawned outside the tree) are culled flat.
    ctx.parallel_for(plants.size() - covered, [&](std::size_t begin, std::size_t end, std::size_t) {
        cull_plants(view, plants, covered + begin, covered + end);
    });
}

}  // namespace

void cull_system::run(ecs::system_context<cull_system>& ctx) {
    const camera& cam = ctx.single<camera>();
    cull_view view{&cam, extract_frustum_planes(cam.projection * cam.view),
                   &ctx.resource<species_library>().species,
                   ctx.resource<shadow_settings>().max_distance_m, 0.0f,
                   ctx.resource<lod_policy>().mode == lod_policy::kind::points_lines ||
                       ctx.resource<lod_policy>().any_ladder_reaches(representation::eco_tile)};
    for (const auto& species : *view.library)
        view.max_species_distance = std::max(view.max_species_distance, species.max_distance_m);
    const plant_query plants =
        ctx.query<const world_transform, const bounds, const plant_instance, lod_state>();
    const auto& tiles = ctx.read<tile>();
    if (tiles.size() == 0) {
        ctx.parallel_for(plants.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
            cull_plants(view, plants, begin, end);
        });
        return;
    }
    auto& visibility = ctx.write<tile_visibility>();
    const std::size_t covered = walk_tiles(view, tiles, visibility);
    cull_tiled(ctx, view, plants, tiles, visibility, covered);
}

}  // namespace sylva
