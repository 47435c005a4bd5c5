#pragma once
// Runs `sylva bench`: renders the supersampled full-geometry reference of every frame of the
// scenario's camera path once, then plays each configuration over the same frames in the same
// process, measuring its time and its error against the reference frame by frame (DESIGN.md §3).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/bench_report.h"
#include "app/scenario_player.h"
#include "models/bake_cache.h"
#include "scenarios/scenario.h"
#include "systems/render/gl_context.h"

namespace sylva {

// One configuration: how to change the scenario and how the player draws it.
struct bench_configuration_spec {
    std::string name;
    std::string family;
    std::string description;
    double quality = 0.0;
    player_options options;     // geometry mode and representation policy (id_buffer is forced on)
    float lod_scale_factor = 1.0f;  // multiplies the scenario's lod_scale
    std::uint32_t samples = 1;      // samples per pixel along each axis (the reference: 3)
};

// Samples per pixel along each axis of the reference (issue 4: at least 3x3).
constexpr std::uint32_t k_bench_reference_samples = 3;
// Viewing condition of the FLIP error: the paper's default (a 0.7 m wide 4K monitor seen from
// 0.7 m, about 67 pixels per degree; Andersson et al. 2020 §4).
constexpr double k_bench_flip_pixels_per_degree = 67.0;
// A plant's colour counts for the lighting jump only where it covers at least this many pixels
// in both frames of the switch, in the test and in the reference: fewer pixels are mostly
// edges, whose colour is the background's as much as the plant's.
constexpr std::uint32_t k_lighting_jump_min_pixels = 12;

// Every configuration Sylva has, in run order: the reference against itself (a check that must
// give zero error), brute force, the runtime's mesh levels and a sweep of their lod_scale, each
// representation on its own, and the engine baseline (full mesh near, crossed billboard beyond
// a distance, hard switch) with a sweep of its switch distance.
std::vector<bench_configuration_spec> default_bench_configurations();

// Where a bench is: the configuration (-1: the reference), the round and the frame.
struct bench_progress {
    int configuration = -1;
    std::size_t configurations = 0;
    std::uint32_t round = 0;
    std::uint32_t rounds = 1;
    std::uint32_t frame = 0;
    std::uint32_t frames = 0;
};

struct bench_settings {
    int threads = 0;
    std::vector<std::string> only;  // configuration names to run (empty: all)
    // When set, every frame is also written as frames_dir/<configuration>/frame_NNNN.png (the
    // reference's as frames_dir/_reference/).
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
};

// Plays `s.frames` frames of `s` per configuration. Throws on GL or file errors.
bench_report run_bench(const scenario& s, const std::vector<bench_configuration_spec>& configurations,
                       render::gl_context& context, bake_cache* cache, bench_settings settings);

// The process's resident-memory high-water mark in MB (VmHWM), and its reset (Linux: writing 5
// to /proc/self/clear_refs), so each configuration reports its own peak.
double peak_resident_mb();
void reset_peak_resident();

}  // namespace sylva
