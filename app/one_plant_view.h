#pragma once
// One plant of a scenario's species alone on flat ground, seen at a chosen projected size: the
// set-up of the measurements that judge a representation of one plant against its full
// geometry (the rung tables, app/rung_tables.h; LoDF's quality, app/lodf_quality_command.cpp).
#include <cstddef>
#include <cstdint>
#include <string>

#include "scenarios/scenario.h"

namespace sylva {

class scenario_player;

inline constexpr float k_one_plant_fov_deg = 50.0f;
// Samples per pixel side of the references they are judged against (3x3).
inline constexpr std::uint32_t k_one_plant_reference_samples = 3;

// Species `i` of `s` alone on flat ground, in a square view of `view_px`; the scenario is named
// after the species and `purpose`.
scenario species_alone(const scenario& s, std::size_t i, std::uint32_t view_px, const std::string& purpose);

// Species `i` of `s` as a patch of its own population (issue 21, "Where the tables fell short"):
// k_patch_plants plants (no more than that population has; one is species_alone's plant at
// the population's sizes) at the density, spacing and sizes of the species' densest population
// in a square around the origin (no wider than k_patch_max_side_m), otherwise set up as
// species_alone. A plant judged in a patch is seen through and beside its neighbours, as a
// frame shows it: a carpet of quads that each lose a little coverage, or a crown whose lower
// half the next trees hide.
inline constexpr double k_patch_plants = 49.0;
inline constexpr double k_patch_max_side_m = 120.0;
scenario species_patch(const scenario& s, std::size_t i, std::uint32_t view_px, const std::string& purpose);

// Looks at the plant nearest the origin from `azimuth_deg` so that its sphere is `size_px` high, the eye
// `eye_height_m` above the ground (level with the plant's centre when negative).
void aim_at_plant(scenario_player& player, float size_px, float azimuth_deg, std::uint32_t view_px,
                  double eye_height_m);

}  // namespace sylva
