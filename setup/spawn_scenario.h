#pragma once
// Fills an ECS world from a scenario and the assets build_scene_assets made of it
// (setup/build_scene_assets.h): the camera, the sun, one entity per plant, LoDF cluster, shell
// tile and ground tile, and the resources the per-frame systems read.
#include <vector>

#include "ecs/world.h"
#include "resources/scene_assets.h"
#include "scenarios/scenario.h"
#include "setup/build_scene_assets.h"
#include "setup/population_ambient.h"

namespace sylva {

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
