#pragma once
// scenarios/tiny.json drawn by its mesh levels, as most of the suite plays it. tiny ships the auto
// ladder like every bundled scenario, and a ladder's rung bakes and error tables cost about 100 s
// per empty bake cache (docs/scenario_format.md): the tests of the frame loop, the goldens, the
// determinism and the commands that play tiny say they want the mesh levels (on the command line
// `--representation mesh_levels`). The ladder has tests of its own (tests/lod/ladder_test.cpp,
// tests/lod/rung_solver_test.cpp, tests/systems/select_representation_budget_test.cpp,
// tests/app/rung_tables_eye_test.cpp), and tests/scenarios/scenario_library_test.cpp checks that
// tiny, as shipped, plays it.
#include <filesystem>

#include "scenarios/scenario_loader.h"

namespace sylva::testing {

inline scenario tiny_with_mesh_levels() {
    scenario s =
        load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) / "scenarios/tiny.json");
    draw_by(s, "mesh_levels");
    return s;
}

}  // namespace sylva::testing
