#include "app/bench_measurements.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "app/bench_format.h"
#include "components/lod_state.h"
#include "ecs/parallel.h"
#include "measure/image_metrics.h"
#include "resources/shell_view.h"

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

// The lighting jump over the complete transitions measured (measure/transition_windows.h), into
// `e`: their mean in (plant, first frame, last frame) order, or NaN when none could be measured.
void add_transitions(bench_error& e, std::vector<bench_transition>& windows, std::uint64_t cut_off) {
    std::stable_sort(windows.begin(), windows.end(), [](const bench_transition& a, const bench_transition& b) {
        return std::tie(a.first_plant, a.from_frame, a.to_frame) < std::tie(b.first_plant, b.from_frame, b.to_frame);
    });
    double sum = 0.0;
    for (const bench_transition& w : windows) {
        if (std::isnan(w.jump)) {
            ++e.transitions_too_small;
            continue;
        }
        sum += w.jump;
        ++e.transitions;
        e.transition_frames += w.to_frame - w.from_frame;
        ++e.transitions_by_kind[w.kind];
    }
    e.transitions_cut_off = cut_off;
    e.lighting_jump = e.transitions ? sum / double(e.transitions) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

void reference_frames::add_frame(std::uint32_t frame, image_rgba8 image, const std::vector<std::uint32_t>& ids) {
    if (images.size() <= frame) {
        images.resize(frame + 1);
        masks.resize(frame + 1);
    }
    add_colors(frame, image, ids);
    masks[frame] = plant_mask(ids);
    images[frame] = std::move(image);
}

void reference_frames::add_colors(std::uint32_t frame, const image_rgba8& image, const std::vector<std::uint32_t>& ids) {
    if (colors.size() <= frame) colors.resize(frame + 1);
    colors[frame] = mean_plant_colors(image, ids);
}

configuration_measurements::configuration_measurements(std::size_t plants, std::uint32_t first, std::uint32_t end,
                                                       std::uint32_t path_frames)
    : m_first(first), m_end(end), m_path_frames(path_frames), m_colors(end), m_transitions(plants) {}

void configuration_measurements::add_replayed_frame(std::uint32_t frame, const ecs::world& world,
                                                    const image_rgba8* image, const std::vector<std::uint32_t>* ids) {
    read_drawn_mixes(world, m_mixes);
    m_transitions.add_frame(m_mixes);
    if (!image || !ids) return;
    m_colors[frame] = mean_plant_colors(*image, *ids);
    if (frame + 1 == m_first) m_previous_image = *image;
}

void configuration_measurements::add_frame(std::uint32_t frame, const frame_record& record, const ecs::world& world,
                                           image_rgba8 image, const std::vector<std::uint32_t>& ids,
                                           const reference_frames& ref) {
    bench_frame out;
    out.frame = frame;
    out.frame_ms = {record.frame_ms};
    out.upload_bytes = double(record.upload_bytes);
    out.cpu_ms = timings_of(record.cpu_ms, record.systems);
    out.gpu_ms = timings_of(record.gpu_ms, record.passes);
    out.primitives = primitives_of(record);
    read_drawn_mixes(world, m_mixes);
    m_transitions.add_frame(m_mixes);

    const image_rgba8& reference = ref.images[frame];
    // The metrics are independent of each other; running them side by side changes no
    // value, only the time the bench takes. (Not tbb::parallel_invoke: its tasks read the
    // functors through references before TSan can be told of the hand-off, ecs/parallel.h.)
    ecs::parallel_for_each_index(3, [&](std::size_t metric) {
        if (metric == 0) out.rmse = rmse(reference, image);
        if (metric == 1) out.ssim = mean_ssim(reference, image);
        if (metric == 2) out.perceptual = flip_error(reference, image, k_bench_flip_pixels_per_degree);
    });
    // Shells blended straight into the frame write no plant IDs (passes/shell_pass.h): the mask
    // cannot see their plants, so the frame's coverage is not measured rather than counted as ground.
    const shell_view* shells = world.try_resource<shell_view>();
    out.coverage_iou = shells && shells->active && !shells->half_resolution
                           ? std::numeric_limits<double>::quiet_NaN()
                           : coverage_iou(ref.masks[frame], plant_mask(ids));
    m_colors[frame] = mean_plant_colors(image, ids);
    if (frame > 0) out.popping = popping_score(image, m_previous_image, reference, ref.images[frame - 1]);
    m_previous_image = std::move(image);
    m_records.push_back(std::move(out));
}

void configuration_measurements::summarize(bench_configuration& out, const reference_frames& ref) {
    out.frame_records = std::move(m_records);
    m_records.clear();
    // The windows whose end was seen in the frames played (the first unchanged frame after
    // them; transition_finder::cut_off_at_start_ending_in), and those the path's end cut off.
    out.transition_records.clear();
    for (const transition_window& w : m_transitions.complete_windows()) {
        if (w.to_frame + 1 < m_first || w.to_frame + 1 >= m_end) continue;
        const double jump = window_lighting_jump(w, m_colors, ref.colors, k_lighting_jump_min_pixels);
        out.transition_records.push_back({w.first_plant, w.plant_count, w.from_frame, w.to_frame,
                                          std::string(transition_kind(w)),
                                          jump < 0.0 ? std::numeric_limits<double>::quiet_NaN() : jump});
    }
    out.transitions_cut_off = m_transitions.cut_off_at_start_ending_in(m_first, m_end) +
                              (m_end == m_path_frames ? m_transitions.open_windows() : 0);
    summarize_records(out);
}

void summarize_records(bench_configuration& c) {
    const std::vector<bench_frame>& frames = c.frame_records;
    c.frames = std::uint32_t(frames.size());
    std::vector<double> all_ms;
    std::size_t rounds = 0;
    for (const bench_frame& f : frames) rounds = std::max(rounds, f.frame_ms.size());
    c.frame_ms_rounds.clear();
    for (std::size_t r = 0; r < rounds; ++r) {
        std::vector<double> round;
        for (const bench_frame& f : frames)
            if (r < f.frame_ms.size()) round.push_back(f.frame_ms[r]);
        c.frame_ms_rounds.push_back(median(round));
        all_ms.insert(all_ms.end(), round.begin(), round.end());
    }
    set_frame_times(c, all_ms);
    std::vector<std::map<std::string, double>> cpu, gpu, primitives;
    std::vector<double> upload;
    for (const bench_frame& f : frames) {
        cpu.push_back(f.cpu_ms);
        gpu.push_back(f.gpu_ms);
        primitives.push_back(f.primitives);
        upload.push_back(f.upload_bytes);
    }
    c.cpu_ms = medians(cpu);
    c.gpu_ms = medians(gpu);
    c.primitives = medians(primitives);
    c.upload_bytes = median(upload);

    bench_error& e = c.error;
    e = {};
    if (!frames.empty()) {
        // Sums in frame order: a merge of shards adds the same values in the same order.
        double squared = 0.0, ssim = 0.0, perceptual = 0.0, iou = 0.0, popping = 0.0;
        std::uint32_t popping_frames = 0;
        for (const bench_frame& f : frames) {
            squared += f.rmse * f.rmse;
            ssim += f.ssim;
            perceptual += f.perceptual;
            iou += f.coverage_iou;
            if (!std::isnan(f.popping)) {
                popping += f.popping;
                ++popping_frames;
            }
        }
        const double n = double(frames.size());
        const double mse = squared / n;
        e.rmse = std::sqrt(mse);
        e.psnr_db = mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
        e.ssim = ssim / n;
        e.perceptual = perceptual / n;
        e.coverage_iou = iou / n;
        e.popping = popping_frames ? popping / popping_frames : 0.0;
    }
    add_transitions(e, c.transition_records, c.transitions_cut_off);
}

void add_baseline_ratios(bench_report& report) {
    for (auto& c : report.configurations) {
        const bench_configuration* baseline = bench_format::family_baseline(report, c.lighting);
        if (!baseline || c.frame_ms_rounds.size() != baseline->frame_ms_rounds.size()) continue;
        c.frame_ms_vs_baseline = bench_format::time_ratio(c, *baseline);
    }
}

void add_timing_round(bench_configuration& c, const std::vector<double>& frame_ms) {
    for (std::size_t i = 0; i < frame_ms.size() && i < c.frame_records.size(); ++i)
        c.frame_records[i].frame_ms.push_back(frame_ms[i]);
}

std::map<std::string, double> cost_map(const primitive_costs& costs) {
    return {{"triangle", costs.triangle}, {"point", costs.point}, {"line", costs.line}};
}

}  // namespace sylva
