#pragma once
// A scenario's species by name: the index every species table of the scene shares (setup/
// spawn_scenario.h species order). The loader has checked every population's species exists;
// an unknown name gives s.species.size().
#include <algorithm>
#include <cstddef>
#include <string_view>

#include "scenarios/scenario.h"

namespace sylva {

inline std::size_t species_index_of(const scenario& s, std::string_view name) {
    return std::size_t(std::find_if(s.species.begin(), s.species.end(),
                                    [&](const species_settings& sp) { return sp.name == name; }) -
                       s.species.begin());
}

}  // namespace sylva
