#pragma once
// Luft 2007 §5: "it is possible to compute the implicit surface for a plant population, which in
// turn allows to incorporate static object-to-object interactions between the individuals. An
// exemplary result is a small tree that is naturally darkened by a nearby large tree due to the
// ambient occlusion effects. Nevertheless, such a scenario cannot be combined with instancing."
//
// Sylva keeps instancing. Each plant's model already carries its own k_a (Eq. 4 of its own field
// F_i, baked once per species). The population's field at a point x is F_i(x) + Σ_j≠i (F_j(x) + τ_j):
// every neighbour adds its generators' density (Eq. 3 without its threshold). What the neighbours
// change is then the factor
//     g(x) = k_a(F_i(x) + Σ_j (F_j(x) + τ_j)) / k_a(F_i(x))      (Eq. 4 with the plant's own
//                                                                   k_a,min, d_min and n)
// which is computed at spawn at the 8 corners of a box around the plant and stored in the instance
// (components/population_ambient.h, 8 bytes); shaders interpolate it and multiply it into the
// model's k_a. At the corners this is the paper's population field exactly; in between it is
// trilinear, so it keeps the large-scale darkening (a neighbour's crown on one side, above) and
// not detail finer than the plant.
//
// Only implicit-lit species take part (they have a field); a species receives when its
// species.implicit.population is set. Fields move with their plants: generators, ρ and the box
// scale with the plant, τ and d_min are densities and do not.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "components/population_ambient.h"
#include "components/transform.h"
#include "ecs/world.h"
#include "models/bake/implicit_illumination.h"
#include "resources/scene_assets.h"
#include "scenarios/scenario.h"

namespace sylva {

// A species' density as its plants carry it, from its unscaled model (the generators and
// defaults the implicit bake used, implicit_illumination.h) scaled by `scale`.
species_density species_density_of(const plant_model& unscaled, const implicit_settings& settings, float scale,
                                   bool receives);

// One plant's field in the world.
struct placed_field {
    const implicit_field* field = nullptr;  // model space at the species' scale
    world_transform transform;
};

// The model-space point of `t`'s plant at world point x (the inverse of shaders/instance.glsl
// pose_instance: turn by −yaw about +y, divide by the scale).
glm::vec3 to_model(const world_transform& t, const glm::dvec3& x);

// g at the 8 corners (components/population_ambient.h order) of the plant `self` with `settings`
// (its species' used settings) and box half size `half_size_m`, under `neighbours`.
std::array<float, k_population_corners> population_factors(const placed_field& self, const implicit_settings& settings,
                                                           float half_size_m, std::span<const placed_field> neighbours);

struct population_report {
    std::size_t receivers = 0;
    std::size_t neighbour_pairs = 0;  // (receiver, neighbour) pairs within reach
    std::size_t darkened = 0;         // receivers with some corner below 1
    float min_factor = 1.0f;
    double seconds = 0.0;
};

// Gives every plant a population_ambient component (aligned with the plant tables) when some
// species receives; does nothing otherwise. Parallel over receivers; each plant's value depends
// only on the scene, so it is the same for any thread count.
population_report bake_population_ambient(ecs::world& world, const scene_assets& assets);

}  // namespace sylva
