#pragma once
// What the auto ladder's solver chooses from (lod/rung_solver.h), as text (`sylva bake
// --print-tables`): per species, each rung's error per pixel of the plant's full geometry (the
// tables' error summed over the plant's pixels, divided by them; of 1) and the cost in
// microseconds of drawing it in the view and of casting its shadow, as the device's calibration
// priced them, at every table size. To see why a plant of some size takes the rung it does.
#include <span>
#include <string>

#include "resources/rung_budget.h"

namespace sylva {

// `species` names the budget's tables in order (a table past the names is "species N").
std::string rung_table_report(const std::string& scenario_name,
                              std::span<const std::string> species, const rung_budget& budget);

}  // namespace sylva
