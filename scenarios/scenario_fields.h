#pragma once
// The scenario format's schema: one field_table per struct of scenarios/scenario.h (each key,
// its range and default, read and written by the same table) and the checks across fields
// (ordered pairs, known species, Wang tiles that fit). scenarios/scenario_loader.cpp turns text
// into the JSON document these read; docs/scenario_format.md describes what they accept.
#include "scenarios/json_reader.h"
#include "scenarios/scenario.h"

namespace sylva {

// The whole document's table: reads a scenario from /, writes one back.
const field_table<scenario>& scenario_fields();

}  // namespace sylva
