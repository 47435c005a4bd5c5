#pragma once
// What a scenario names from outside, read so that bad input says where it is: a file that cannot
// be used becomes a scenario_error naming the scenario, the field and the file; a warning about
// the scenario is said once per process. Shared by build_scene_assets and spawn_scenario.
#include <spdlog/spdlog.h>

#include <nlohmann/json.hpp>
#include <string>

#include "io/once_per_process.h"
#include "scenarios/scenario.h"
#include "scenarios/scenario_loader.h"

namespace sylva {

// A scenario's warning once per process (io/once_per_process.h).
inline void warn_once(const std::string& message) {
    if (first_time_in_process("scenario warning", message)) spdlog::warn("{}", message);
}

// Reads a file the scenario names (field `pointer`, a JSON Pointer); a file that cannot be used
// is bad input: a scenario_error naming the scenario, the field, the file and the problem,
// thrown before any output exists. Only `Error` is converted: the bake cache's own disk errors
// stay runtime failures.
template <class Error, class Load>
auto read_named_file(const scenario& s, const std::string& pointer, const std::string& file,
                     const Load& load) -> decltype(load()) {
    try {
        return load();
    } catch (const scenario_error&) {
        throw;
    } catch (const Error& e) {
        throw scenario_error(s.source, pointer, nlohmann::json(file).dump(), e.what());
    }
}

}  // namespace sylva
