#pragma once
// Turns a scenario into something to draw: builds the scene's meshes, textures and terrain
// (build_scene_assets, CPU only) and fills an ECS world with the camera, the sun and one entity
// per plant plus the resources the per-frame systems read (spawn_scenario).
#include <functional>
#include <string>

#include "setup/population_ambient.h"
#include "ecs/world.h"
#include "models/cache/bake_cache.h"
#include "scenarios/scenario.h"
#include "resources/scene_assets.h"

namespace sylva {

// What a scene bakes beyond the mesh levels and crossed billboards: only what its LOD policy
// can select (DESIGN §2, "skip what a scene doesn't need").
struct scene_needs {
    bool point_lines = false;  // Deussen 2002 points and lines (setup/point_line_assets.h)
    bool billboard_clouds = false;  // Behrendt 2005 billboard clouds (models/bake/billboard_cloud.h)
    bool lodf = false;  // Rebollo 2006 LoDF foliage (models/bake/lodf_bake.h)
    bool shells = false;  // Behrendt 2005 §3 shell textures of the Wang tiles (setup/shell_assets.h)
    // The crossed billboard with one quad turned to the eye (representation::facing_billboard): no
    // bake of its own, but its mesh and programs only when a ladder can choose it.
    bool facing_billboards = false;
};

// Called as the species are baked (or read from the cache): the share done, 0..1, and the step.
using bake_progress = std::function<void(float done, const std::string& step)>;

// `cache` may be null: species models are then generated or imported every time.
scene_assets build_scene_assets(const scenario& s, bake_cache* cache, const scene_needs& needs = {},
                                const bake_progress& progress = {});

struct spawn_report {
    std::size_t plants = 0;
    std::size_t requested = 0;  // what the populations asked for (placement may fit fewer)
    population_report population;  // Luft 2007 §5, when a species asks for it
};

// Creates the entities and resources; aligns the plant component tables so every per-frame
// query over plants is a linear walk.
spawn_report spawn_scenario(ecs::world& world, const scenario& s, const scene_assets& assets);

// Rebollo 2006: when a species has LoDF clusters, `slot_count` (lod.lodf_slots) slots of
// foliage-cluster entities (one per cluster of the species with the most), slot by slot, and the
// slots resource over them (resources/lodf_slots.h); an empty resource otherwise. Part of
// spawn_scenario, and for worlds built by hand (tests, benchmarks).
void spawn_lodf_clusters(ecs::world& world, const species_library& library, std::uint32_t slot_count);
// Behrendt 2005 §3: with shell textures, a shell_tile entity per terrain tile and the shell_view
// resource (inactive without shells). Part of spawn_scenario.
void spawn_shells(ecs::world& world, const scenario& s, const scene_assets& assets);
// One ground_tile entity per terrain tile, its grids' errors from scene_assets::terrain_grid_errors
// (components/ground_tile.h); none when the assets have no grids (scenes built by hand).
void spawn_ground_tiles(ecs::world& world, const scenario& s, const scene_assets& assets);

// Scenario keyframes with heights above the terrain resolved to absolute world positions.
std::vector<camera_keyframe> resolve_camera_keys(const scenario& s, const heightfield& terrain);

}  // namespace sylva
