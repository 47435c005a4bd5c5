#pragma once
// What one configuration's frames add up to in `sylva bench` (DESIGN.md §3): frame times, CPU
// time per system, GPU time per pass, primitives and uploads as medians over its frames; its
// errors against its lighting family's reference as means over them; and the lighting jump
// over the transitions its plants went through. app/bench_runner.cpp plays the frames and hands
// each here; app/bench_report.h is where the results land.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "app/bench_report.h"
#include "app/drawn_mix.h"
#include "app/metrics.h"
#include "ecs/world.h"
#include "measure/temporal_metrics.h"
#include "measure/transition_windows.h"
#include "models/image/image.h"
#include "lod/point_line_lod.h"

namespace sylva {

// Viewing condition of the FLIP error: the paper's default (a 0.7 m wide 4K monitor seen from
// 0.7 m, about 67 pixels per degree; Andersson et al. 2020 §4).
constexpr double k_bench_flip_pixels_per_degree = 67.0;
// A plant's (or eco tile's) colour counts for the lighting jump only where it covers at least
// this many pixels at both ends of its transition, in the test and in the reference: fewer
// pixels are mostly edges, whose colour is the background's as much as the plant's.
constexpr std::uint32_t k_lighting_jump_min_pixels = 12;

// What the configurations of one lighting family are compared against, indexed by frame of the
// path: images and masks of the frames played (and of the frame before a shard's first, for
// popping), colours also of the frames a shard's transitions began in (empty elsewhere).
struct reference_frames {
    std::vector<image_rgba8> images;
    std::vector<std::vector<std::uint8_t>> masks;
    std::vector<plant_colors> colors;
    std::vector<double> frame_ms;  // of the frames played, in order

    // Frame `frame` (resolved to the output size) with its plant IDs at the same size.
    void add_frame(std::uint32_t frame, image_rgba8 image, const std::vector<std::uint32_t>& ids);
    // Only its colours (a transition's first frame before a shard).
    void add_colors(std::uint32_t frame, const image_rgba8& image, const std::vector<std::uint32_t>& ids);
};

// Round 0 of one configuration (bench_settings::timing_rounds), frame by frame.
class configuration_measurements {
public:
    // `plants`: the scenario's plant count (the transition finder follows each). `played`: the
    // frames measured, [first, end) of the path; the transitions kept are those ending there.
    configuration_measurements(std::size_t plants, std::uint32_t first, std::uint32_t end, std::uint32_t path_frames);

    // A frame before the first played (a shard's replay, in order from frame 0): what each
    // plant was drawn as, and when it was rendered its image and plant IDs (the frame before
    // the first is the popping's previous frame; others are transitions' first frames).
    void add_replayed_frame(std::uint32_t frame, const ecs::world& world, const image_rgba8* image,
                            const std::vector<std::uint32_t>* ids);
    // The frames whose colours the transitions still open after the replay began in (a shard
    // needs the reference's colours there too).
    std::vector<std::uint32_t> open_transition_starts() const { return m_transitions.open_from_frames(); }

    // Frame `frame` as played: `record` from the player, what each plant of `world` was drawn
    // as, and the resolved `image` and plant `ids` compared with the reference's frame.
    void add_frame(std::uint32_t frame, const frame_record& record, const ecs::world& world,
                   image_rgba8 image, const std::vector<std::uint32_t>& ids, const reference_frames& ref);

    // Moves the frame records into `out` and measures the transitions that ended in the frames
    // played against `ref` (which must hold the colours of their first frames), then fills its
    // figures (summarize_records).
    void summarize(bench_configuration& out, const reference_frames& ref);

private:
    std::uint32_t m_first, m_end, m_path_frames;
    std::vector<bench_frame> m_records;
    image_rgba8 m_previous_image;
    std::vector<plant_colors> m_colors;  // by frame of the path
    std::vector<drawn_mix> m_mixes;
    transition_finder m_transitions;
};

// Fills a configuration's figures (frame times and their medians, errors, transitions) from
// its records: a whole bench, a shard and a merge of shards all compute them here, in frame
// order, so a merged report equals the whole bench bit for bit (timings apart).
void summarize_records(bench_configuration& c);

// Ratios to the baseline of each configuration's lighting family, round by round, for
// configurations timed in as many rounds as it (not the reference: its one round says nothing
// about drift).
void add_baseline_ratios(bench_report& report);

// Adds a later timing round's frame times (in frame order) to `c`'s records.
void add_timing_round(bench_configuration& c, const std::vector<double>& frame_ms);

// Primitive costs as the report keys them: triangle, point, line.
std::map<std::string, double> cost_map(const primitive_costs& costs);

}  // namespace sylva
