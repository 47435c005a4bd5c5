#pragma once
// A crowd of plants on the LoDF rung (Rebollo 2006), for the cluster system's thread-count
// determinism test and its benchmark (issue 23's ECS cost): `count` trees of one species baked
// for real (models/bake/lodf_bake.h), on a jittered grid 8 m apart, every one on the lodf rung
// of a ladder mesh_full → lodf (below 400 px, no band) → billboard cloud, each in a slot of its own
// (setup/spawn_scenario.h spawn_lodf_clusters with as many slots as plants), and a camera that
// walks diagonally across the grid so every plant's projected size, and so its leaf count,
// changes every frame. The schedule runs update_lodf alone: what it costs is the clusters' walk.
#include <cmath>
#include <glm/geometric.hpp>
#include <span>

#include "components/camera.h"
#include "components/cluster_changes.h"
#include "components/fade_alpha.h"
#include "components/lod_state.h"
#include "components/plant_instance.h"
#include "components/transform.h"
#include "ecs/schedule.h"
#include "ecs/world.h"
#include "models/bake/lodf_bake.h"
#include "resources/lod_policy.h"
#include "resources/lodf_slots.h"
#include "resources/scene_assets.h"
#include "setup/spawn_scenario.h"
#include "systems/update_camera_system.h"
#include "systems/update_lodf_system.h"

namespace sylva::testing {

struct lodf_crowd {
    ecs::world world;
    ecs::schedule schedule;
    std::uint32_t side = 0;  // plants per row

    // `model`: the species' baked LoDF, of `full` (the plant's full mesh).
    lodf_crowd(std::uint32_t count, const lodf_model& model, const mesh_data& full) {
        const float radius = 0.5f * glm::length(full.bounds_max - full.bounds_min);
        side = std::uint32_t(std::ceil(std::sqrt(double(count))));
        species_library library;
        species_entry species;
        species.name = "crowd";
        species.bounding_radius = radius;
        species.center_height = radius;
        species.lodf_clusters = std::uint32_t(model.structure.clusters.size());
        species.lodf_leaves = model.structure.leaf_count;
        library.species.push_back(species);
        library.lodf.push_back(model.structure);
        for (std::uint32_t i = 0; i < count; ++i) {
            const ecs::entity e = world.create();
            const double x = (double(i % side) + 0.3 * std::sin(double(i) * 12.9898)) * 8.0;
            const double z = (double(i / side) + 0.3 * std::cos(double(i) * 78.233)) * 8.0;
            world.emplace<world_transform>(e, {{x, 0.0, z}, float(i % 628) * 0.01f, 0.8f + 0.05f * float(i % 9)});
            world.emplace<plant_instance>(e, {species_id(0), std::uint16_t(i), i});
            world.emplace<lod_state>(e, {representation::lodf});
            world.emplace<fade_alpha>(e);
        }
        world.align<world_transform, plant_instance, lod_state, fade_alpha>();
        spawn_lodf_clusters(world, library, count);
        ladder l;
        l.rungs = {representation::mesh_full, representation::lodf, representation::billboard_cloud};
        l.below_px = {0.0f, 400.0f, 40.0f};
        l.band = {0.0f, 0.0f, 0.15f};  // lod/ladder.h seamless_step: no band into LoDF
        l.count = 3;
        lod_policy policy;
        policy.mode = lod_policy::kind::ladder;
        policy.ladders = {l};
        world.set_resource(std::move(policy));
        world.set_resource(std::move(library));
        world.emplace<camera>(world.create());
        schedule.add<update_lodf_system>();
        schedule.build();
        place_camera(0);
    }

    // Frame f of the walk: 1.5 m further along the grid's diagonal each frame, 6 m up.
    void place_camera(std::uint32_t frame) {
        camera& cam = world.single<camera>();
        const double along = -10.0 + 1.5 * double(frame);
        cam.position = {along, 6.0, along};
        cam.forward = glm::normalize(glm::vec3(1.0f, -0.1f, 1.0f));
        derive_camera_matrices(cam);
    }

    std::uint64_t state_hash() {
        const auto& clusters = world.table<cluster_changes>();
        return lodf_state_hash(world.resource<lodf_slots>(), std::span(clusters.data(), clusters.size()),
                               0xcbf29ce484222325ULL);
    }
};

}  // namespace sylva::testing
