#pragma once
// The configurations `sylva bench` compares (DESIGN.md §3): what each draws and how it is named.
// Running them is app/bench_runner.h's business; reporting them app/bench_report.h's.
//
// Two properties group them. The representation family (`family`) says what a configuration
// varies: the engine baseline's sweep, the runtime's mesh levels, points and lines, billboard
// clouds... The lighting (`options.lighting`) decides which reference its errors are measured
// against (lighting_family below): a configuration lit by SH transfer is compared with an SH-lit
// reference, so each lighting has its own brute force and baseline sweep here.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/scenario_options.h"
#include "app/scenario_player.h"
#include "scenarios/scenario.h"

namespace sylva {

// One configuration: how to change the scenario and how the player draws it.
struct bench_configuration_spec {
    std::string name;
    std::string family;
    std::string description;
    double quality = 0.0;    // the swept setting's value (the baseline's: its switch distance)
    player_options options;  // geometry mode and representation policy (id_buffer is forced on)
    float lod_scale_factor = 1.0f;  // multiplies the scenario's lod_scale
    std::uint32_t samples = 1;      // samples per pixel along each axis (the reference: 3)
};

// Samples per pixel along each axis of the reference (issue 4: at least 3x3).
inline constexpr std::uint32_t k_bench_reference_samples = 3;

// Representation families with a fixed meaning in the reports.
inline constexpr const char* k_family_reference = "reference";
inline constexpr const char* k_family_brute_force = "brute_force";
// The engine baseline's sweep: full mesh near, one crossed-quad billboard beyond a switch
// distance (`quality`, metres x plant scale; 0: the billboard everywhere), hard switch.
inline constexpr const char* k_family_baseline = "baseline";
// The switch distance of the configuration called "the baseline" (`baseline`, `baseline_sh`):
// time ratios are given against it.
inline constexpr double k_named_baseline_distance_m = 50.0;

// The lighting family of a configuration lit `lighting` (player_options::lighting; empty: as the
// scenario says) in scenario `s`: "normal" for normal-mapped and pre-lit (their references are
// one image: full geometry draws no clouds), "sh", or "scenario" when the scenario's species are
// lit in more than one way and the configuration keeps them so.
std::string lighting_family(const scenario& s, const std::string& lighting);

// One sentence on what a lighting family's configurations are lit by, for the reports.
std::string lighting_family_description(const std::string& family);

// What lighting family `family`'s reference draws: every plant at full geometry with
// k_bench_reference_samples along each axis, lit as the scenario says when that is the family
// (so the reference is the one `sylva play --reference` writes), else every species lit the
// family's way.
bench_configuration_spec reference_configuration(const scenario& s, const std::string& family);

// Every configuration Sylva has, in run order: the reference against itself (a check that must
// give zero error), brute force, the runtime's mesh levels and a sweep of their lod_scale, each
// representation on its own, the engine baseline's sweep, billboard clouds, points and lines,
// and the SH-lit twins of brute force, the baseline sweep and the main configurations.
std::vector<bench_configuration_spec> default_bench_configurations();

// Whether `c` measures anything on `s` that another configuration does not: the shells family
// only where a population is Wang-tiled (elsewhere each of its configurations draws `ladder`).
bool applies_to(const bench_configuration_spec& c, const scenario& s);

// What the representation options on the command line (--representation, --sample-distance,
// --splats, --primitive-budget, --target-frame-ms) ask the bench to measure besides its own
// configurations: the configuration `sylva play` with the same options draws, named as the
// catalogue names it (so `--sample-distance 2 --representation points_lines` is
// `points_lines_d2`). Nothing when none of them is given. Throws std::invalid_argument naming
// the option when one does not apply to the representation (d' and budgets are points and
// lines' only).
std::optional<bench_configuration_spec> command_line_configuration(const scenario& s,
                                                                   const scenario_options& o);

}  // namespace sylva
