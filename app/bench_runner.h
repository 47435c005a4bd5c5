#pragma once
// Runs `sylva bench`: renders the supersampled full-geometry reference of every frame of the
// scenario's camera path once per lighting family, then plays each configuration over the same
// frames in the same process, measuring its time and its error against its family's reference
// frame by frame (DESIGN.md §3). The configurations themselves and their lighting families are
// app/bench_catalogue.h's; what a configuration's frames add up to is app/bench_measurements.h's.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/bench_catalogue.h"
#include "app/bench_report.h"
#include "app/frame_range.h"
#include "app/scenario_player.h"
#include "models/cache/bake_cache.h"
#include "scenarios/scenario.h"
#include "systems/render/gl_context.h"

namespace sylva {

// Where a bench is: the configuration (-1: a reference), the round and the frame.
struct bench_progress {
    int configuration = -1;
    std::size_t configurations = 0;
    std::uint32_t round = 0;
    std::uint32_t rounds = 1;
    std::uint32_t frame = 0;
    std::uint32_t frames = 0;
    std::string reference_lighting;  // while rendering a reference: its family
};

struct bench_settings {
    int threads = 0;
    std::vector<std::string> only;  // configuration names to run (empty: all)
    // When set, every frame is also written as frames_dir/<configuration>/frame_NNNN.png (each
    // reference's as frames_dir/_reference_<lighting family>/).
    std::filesystem::path frames_dir;
    // Each configuration's frames are played this many times for its timing: round 0 measures
    // errors and time, the rounds after it time the same frames again (read back the same way,
    // so the device syncs at the same points), the configurations alternating so a machine
    // that slows down or speeds up over a run shifts them all alike. Frame times are medians
    // over every round's frames; errors come from round 0 alone (they do not vary). The
    // `reference` configuration (a check that the comparison is exact) is timed in round 0 only.
    std::uint32_t timing_rounds = 1;
    // Called before every frame for progress output.
    std::function<void(const bench_progress&)> progress;
    // Asked after every frame; true ends the bench there (an interrupt): the report keeps what
    // was measured, with the configuration in progress cut at its last frame, and is partial.
    std::function<bool()> stop;
    // Fixed primitive costs for every point/line configuration (tests: a measurement differs
    // run to run). Unset: each configuration selects with the device's costs for its own d'
    // (scenario_player: from the cache, measured on first use), as `sylva play` with the same
    // options does, so its errors do not depend on which other configurations run with it.
    std::optional<primitive_costs> costs;
    // A shard (issue 25): only frames [first, end) of the path are measured, exactly as the
    // whole bench measures them (each player replays the frames before, scenario_player::
    // replay_to); `sylva merge` joins shards. Unset: every frame.
    std::optional<frame_range> range;
};

// Plays `s.frames` frames of `s` per configuration. Throws std::invalid_argument for an unknown
// --only name, std::runtime_error on GL or file errors.
bench_report run_bench(const scenario& s, const std::vector<bench_configuration_spec>& configurations,
                       render::gl_context& context, bake_cache* cache, bench_settings settings);

}  // namespace sylva
