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

// What the configurations of one lighting family are compared against, one entry per frame.
struct reference_frames {
    std::vector<image_rgba8> images;
    std::vector<std::vector<std::uint8_t>> masks;
    std::vector<plant_colors> colors;
    std::vector<double> frame_ms;

    // Frame `image` (resolved to the output size) with its plant IDs at the same size.
    void add_frame(double frame_ms, image_rgba8 image, const std::vector<std::uint32_t>& ids);
};

// Round 0 of one configuration (bench_settings::timing_rounds), frame by frame.
class configuration_measurements {
public:
    // `plants`: the scenario's plant count (the transition finder follows each).
    explicit configuration_measurements(std::size_t plants);

    // Frame `frame` as played: `record` from the player, what each plant of `world` was drawn
    // as, and the resolved `image` and plant `ids` compared with the reference's frame.
    void add_frame(std::uint32_t frame, const frame_record& record, const ecs::world& world,
                   image_rgba8 image, const std::vector<std::uint32_t>& ids, const reference_frames& ref);

    // Fills `out`'s frame count, times, medians, errors and transitions from the frames added.
    void summarize(bench_configuration& out, const reference_frames& ref) const;

    const std::vector<double>& frame_ms() const { return m_frame_ms; }

private:
    // Per-frame error sums.
    double m_squared_error = 0.0;  // sum over frames of rmse^2 (every frame has the same pixels)
    double m_ssim = 0.0;
    double m_perceptual = 0.0;
    double m_coverage_iou = 0.0;
    double m_popping = 0.0;
    std::uint32_t m_popping_frames = 0;

    std::vector<double> m_frame_ms;
    std::vector<double> m_upload;
    std::vector<std::map<std::string, double>> m_cpu, m_gpu, m_primitives;
    image_rgba8 m_previous_image;
    std::vector<plant_colors> m_colors;
    std::vector<drawn_mix> m_mixes;
    transition_finder m_transitions;
};

// Folds the later timing rounds into `c`: medians, extremes and round medians over every
// round's frames (round 0's are `c`'s own).
void add_timing_rounds(bench_configuration& c, std::vector<double> round0_frame_ms,
                       const std::vector<std::vector<double>>& later_rounds);

// Primitive costs as the report keys them: triangle, point, line.
std::map<std::string, double> cost_map(const primitive_costs& costs);

}  // namespace sylva
