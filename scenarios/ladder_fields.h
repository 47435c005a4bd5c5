#pragma once
// The `ladder` arrays of a scenario's lod section and of a species (scenarios/scenario.h): read,
// checked as a whole with the runtime's own rules (lod/ladder.h find_ladder_problem, so a ladder
// the loader accepts is one the runtime can draw) and written back; an empty ladder is not
// written. Apart from scenario_fields.cpp because two tables share it.
#include <nlohmann/json.hpp>
#include <vector>

#include "lod/ladder.h"
#include "scenarios/json_reader.h"
#include "scenarios/scenario.h"

namespace sylva {

// Fails naming /…/ladder/<i>/<field> for the rung at fault.
void read_ladder(const json_node& node, std::vector<ladder_step_settings>& out);
void write_ladder(const std::vector<ladder_step_settings>& steps, nlohmann::json& parent);

// The runtime's ladder for checked steps (their rung names valid).
ladder ladder_of(const std::vector<ladder_step_settings>& steps);

}  // namespace sylva
