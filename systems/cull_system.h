#pragma once
// View-frustum and distance culling of plant instances, in parallel chunks: a plant is visible
// when its bounding sphere touches the camera frustum and it is nearer than its species' draw
// distance (under the point/line policy: at any distance); it may cast shadows when it is
// within the shadow distance. Writes lod_state.
//
// With eco tiles (Deussen 2002 §6.2; lod/eco_tiles.h) the tiles are walked from the roots
// first: a tile whose box (square and terrain height range grown by the plants' reach) is
// outside the frustum and beyond every draw and shadow distance is culled with its whole
// subtree, and only the plants of surviving leaf tiles are tested one by one; the plants of
// culled tiles get visible = 0 and in_shadow_range = 0 without being looked at. The result for
// each plant is the same as flat culling would give it whenever its tile survives. Writes
// tile_visibility for every tile. Without tile entities every plant is tested (flat culling).
//
// Precondition with tiles: plant dense index i (the world_transform table's order) is eco tile
// slot i, i.e. the spawner created plants in eco_tile_tree::order and aligned the plant tables;
// plants beyond the tiles' ranges are culled flat. Checked per leaf on its first plant.
#include "components/bounds.h"
#include "components/camera.h"
#include "components/lod_state.h"
#include "components/plant_instance.h"
#include "components/tile.h"
#include "components/tile_visibility.h"
#include "components/transform.h"
#include "ecs/system.h"
#include "scenarios/scenario.h"
#include "resources/lod_policy.h"
#include "resources/scene_assets.h"

namespace sylva {

// The six planes of a camera-relative frustum, normals pointing inside (Gribb & Hartmann 2001:
// planes from the rows of the view-projection matrix), normalised.
struct frustum_planes {
    glm::vec4 planes[6];
};
frustum_planes extract_frustum_planes(const glm::mat4& view_projection);
bool sphere_in_frustum(const frustum_planes& f, glm::vec3 center, float radius);
// Conservative box test: false only when the box is wholly outside one plane.
bool box_in_frustum(const frustum_planes& f, glm::vec3 lo, glm::vec3 hi);

// Tiles per parallel chunk of the plant pass (fixed: results never depend on threads). Not the
// context's chunk(), which counts plant entities: a leaf tile stands for up to
// max_plants_per_tile plants, so 8 tiles make a task of the order of a 4096-plant chunk. It can
// not change a result: each tile writes only its own plants' lod_state and the loop has no
// per-chunk output to merge. Any scene of more than 16 tiles runs it in three chunks or more
// (tests/determinism/chunk_boundary_determinism_test.cpp checks that its scene does).
inline constexpr std::size_t k_cull_tile_chunk = 8;

struct cull_system {
    static constexpr std::string_view k_name = "cull";
    static constexpr ecs::phase k_phase = ecs::phase::cull;
    using reads = ecs::reads<camera, world_transform, bounds, plant_instance, tile, species_library,
                             shadow_settings, lod_policy>;
    using writes = ecs::writes<lod_state, tile_visibility>;
    static void run(ecs::system_context<cull_system>& ctx);
};

}  // namespace sylva
