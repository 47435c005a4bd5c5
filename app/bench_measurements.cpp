#include "app/bench_measurements.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "components/lod_state.h"
#include "ecs/parallel.h"
#include "measure/image_metrics.h"

namespace sylva {
namespace {


// Medians per key over frames (a key missing in a frame counts as 0 there).
std::map<std::string, double> medians(const std::vector<std::map<std::string, double>>& frames) {
    std::map<std::string, std::vector<double>> columns;
    for (const auto& f : frames)
        for (const auto& [key, value] : f) columns[key];
    for (const auto& f : frames)
        for (auto& [key, values] : columns) {
            const auto it = f.find(key);
            values.push_back(it == f.end() ? 0.0 : it->second);
        }
    std::map<std::string, double> out;
    for (auto& [key, values] : columns) out[key] = median(std::move(values));
    return out;
}

// A frame's milliseconds keyed by system (or pass), with their sum as "total".
std::map<std::string, double> timings_of(double total, const std::vector<std::pair<std::string, double>>& parts) {
    std::map<std::string, double> out{{"total", total}};
    for (const auto& [name, ms] : parts) out[name] = ms;
    return out;
}

std::map<std::string, double> primitives_of(const frame_record& r) {
    std::map<std::string, double> p{{"triangles", double(r.triangles)},
                                    {"shadow_triangles", double(r.shadow_triangles)},
                                    {"points", double(r.points)},
                                    {"lines", double(r.lines)}};
    if (r.work_counted) {
        p["vertices"] = double(r.vertices);
        p["fragments"] = double(r.fragments);
        p["shadow_vertices"] = double(r.shadow_vertices);
        p["shadow_fragments"] = double(r.shadow_fragments);
    }
    for (std::size_t i = 1; i < r.instances.size(); ++i)
        p["instances_" + std::string(representation_name(static_cast<representation>(i)))] = double(r.instances[i]);
    return p;
}

// Median, fastest and slowest of `frame_ms` into `c` (0 when there are none).
void set_frame_times(bench_configuration& c, const std::vector<double>& frame_ms) {
    c.frame_ms_median = median(frame_ms);
    c.frame_ms_min = frame_ms.empty() ? 0.0 : *std::min_element(frame_ms.begin(), frame_ms.end());
    c.frame_ms_max = frame_ms.empty() ? 0.0 : *std::max_element(frame_ms.begin(), frame_ms.end());
}

// The lighting jump over every complete transition `finder` found (measure/transition_windows.h),
// into `e`: their mean, or NaN when none could be measured.
void add_transitions(bench_error& e, const transition_finder& finder, const std::vector<plant_colors>& test,
                     const reference_frames& ref) {
    double sum = 0.0;
    for (const transition_window& w : finder.complete_windows()) {
        const double jump = window_lighting_jump(w, test, ref.colors, k_lighting_jump_min_pixels);
        if (jump < 0.0) {
            ++e.transitions_too_small;
            continue;
        }
        sum += jump;
        ++e.transitions;
        e.transition_frames += w.to_frame - w.from_frame;
        ++e.transitions_by_kind[transition_kind(w)];
    }
    e.transitions_cut_off = finder.incomplete_windows();
    e.lighting_jump = e.transitions ? sum / double(e.transitions) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

void reference_frames::add_frame(double ms, image_rgba8 image, const std::vector<std::uint32_t>& ids) {
    frame_ms.push_back(ms);
    masks.push_back(plant_mask(ids));
    colors.push_back(mean_plant_colors(image, ids));
    images.push_back(std::move(image));
}

configuration_measurements::configuration_measurements(std::size_t plants) : m_transitions(plants) {}

void configuration_measurements::add_frame(std::uint32_t frame, const frame_record& record, const ecs::world& world,
                                           image_rgba8 image, const std::vector<std::uint32_t>& ids,
                                           const reference_frames& ref) {
    m_frame_ms.push_back(record.frame_ms);
    m_upload.push_back(double(record.upload_bytes));
    m_cpu.push_back(timings_of(record.cpu_ms, record.systems));
    m_gpu.push_back(timings_of(record.gpu_ms, record.passes));
    m_primitives.push_back(primitives_of(record));
    read_drawn_mixes(world, m_mixes);
    m_transitions.add_frame(m_mixes);

    const image_rgba8& reference = ref.images[frame];
    // The metrics are independent of each other; running them side by side changes no
    // value, only the time the bench takes. (Not tbb::parallel_invoke: its tasks read the
    // functors through references before TSan can be told of the hand-off, ecs/parallel.h.)
    double e_rmse = 0.0, e_ssim = 0.0, e_flip = 0.0;
    ecs::parallel_for_each_index(3, [&](std::size_t metric) {
        if (metric == 0) e_rmse = rmse(reference, image);
        if (metric == 1) e_ssim = mean_ssim(reference, image);
        if (metric == 2) e_flip = flip_error(reference, image, k_bench_flip_pixels_per_degree);
    });
    m_squared_error += e_rmse * e_rmse;
    m_ssim += e_ssim;
    m_perceptual += e_flip;
    m_coverage_iou += coverage_iou(ref.masks[frame], plant_mask(ids));
    m_colors.push_back(mean_plant_colors(image, ids));
    if (frame > 0) {
        m_popping += popping_score(image, m_previous_image, reference, ref.images[frame - 1]);
        ++m_popping_frames;
    }
    m_previous_image = std::move(image);
}

void configuration_measurements::summarize(bench_configuration& out, const reference_frames& ref) const {
    out.frames = std::uint32_t(m_frame_ms.size());
    set_frame_times(out, m_frame_ms);
    out.frame_ms_rounds = {out.frame_ms_median};
    out.cpu_ms = medians(m_cpu);
    out.gpu_ms = medians(m_gpu);
    out.primitives = medians(m_primitives);
    out.upload_bytes = median(m_upload);

    bench_error& e = out.error;
    e = {};
    if (const std::uint32_t frames = out.frames) {
        const double mse = m_squared_error / frames;
        e.rmse = std::sqrt(mse);
        e.psnr_db = mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
        e.ssim = m_ssim / frames;
        e.perceptual = m_perceptual / frames;
        e.coverage_iou = m_coverage_iou / frames;
        e.popping = m_popping_frames ? m_popping / m_popping_frames : 0.0;
    }
    add_transitions(e, m_transitions, m_colors, ref);
}

void add_timing_rounds(bench_configuration& c, std::vector<double> round0_frame_ms,
                       const std::vector<std::vector<double>>& later_rounds) {
    std::vector<double> all = std::move(round0_frame_ms);
    for (const auto& round : later_rounds) {
        c.frame_ms_rounds.push_back(median(round));
        all.insert(all.end(), round.begin(), round.end());
    }
    if (!all.empty()) set_frame_times(c, all);
}

std::map<std::string, double> cost_map(const primitive_costs& costs) {
    return {{"triangle", costs.triangle}, {"point", costs.point}, {"line", costs.line}};
}

}  // namespace sylva
