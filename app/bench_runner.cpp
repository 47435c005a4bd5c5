#include "app/bench_runner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <thread>

#include "app/bench_format.h"
#include "app/drawn_mix.h"
#include "app/metrics.h"
#include "app/process_memory.h"
#include "components/lod_state.h"
#include "ecs/parallel.h"
#include "measure/image_metrics.h"
#include "measure/temporal_metrics.h"
#include "measure/transition_windows.h"
#include "models/image/image_ops.h"
#include "models/generate/textures.h"

namespace sylva {
namespace {

// What the configurations of one lighting family are compared against, one entry per frame.
struct reference_frames {
    std::vector<image_rgba8> images;
    std::vector<std::vector<std::uint8_t>> masks;
    std::vector<plant_colors> colors;
    std::vector<double> frame_ms;
};

// Per-frame error sums of one configuration.
struct error_accumulator {
    double squared_error = 0.0;  // sum over frames of rmse^2 (every frame has the same pixels)
    double ssim = 0.0;
    double perceptual = 0.0;
    double coverage_iou = 0.0;
    double popping = 0.0;
    std::uint32_t frames = 0;
    std::uint32_t popping_frames = 0;

    bench_error result() const {
        bench_error e;
        if (frames == 0) return e;
        const double mse = squared_error / frames;
        e.rmse = std::sqrt(mse);
        e.psnr_db = mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
        e.ssim = ssim / frames;
        e.perceptual = perceptual / frames;
        e.coverage_iou = coverage_iou / frames;
        e.popping = popping_frames ? popping / popping_frames : 0.0;
        return e;
    }
};

// Species lit by SH transfer, and the scenario's species count.
std::size_t sh_species(const scenario& s) {
    return std::size_t(std::count_if(s.species.begin(), s.species.end(), [&](const species_settings& sp) {
        return (sp.lighting == "scenario" ? s.lod.lighting : sp.lighting) == "sh";
    }));
}

// The player_options::lighting a family's reference is drawn with: the scenario's own when the
// family is what the scenario draws anyway (so its reference is the one `play --reference`
// writes), else every species lit the family's way.
std::string reference_lighting(const scenario& s, const std::string& family) {
    if (family == lighting_family(s, "")) return "";
    return family == "sh" ? "sh" : "normal_mapped";
}

std::string family_description(const std::string& family) {
    if (family == "sh") return "every species lit by SH transfer (Behrendt 2005 §4)";
    if (family == "normal") return "every species lit by its normals (normal-mapped; pre-lit clouds compare here too)";
    return "every species lit as the scenario says (its species are lit in different ways)";
}

scenario configured(const scenario& s, const bench_configuration_spec& c) {
    scenario out = s;
    out.camera.lod_scale = s.camera.lod_scale * c.lod_scale_factor;
    out.width = s.width * c.samples;
    out.height = s.height * c.samples;
    return out;
}

// How the player of configuration `spec` draws: what it names exactly (not the scenario's lod
// section), with an ID buffer, and with the bench's fixed costs when it has them.
player_options configuration_options(const bench_configuration_spec& spec, const bench_settings& settings) {
    player_options options = spec.options;
    options.id_buffer = true;
    options.scenario_lod = false;
    if (settings.costs) {
        options.costs = *settings.costs;
        options.measure_costs = false;
    }
    return options;
}

// Plays frame 0 once and rewinds, so shader compilation and first-use allocation are not timed
// (each configuration has its own renderer). Playback is a function of the frame number, so
// the frames that follow are the same as without it.
void warm_up(scenario_player& player) {
    player.step();
    player.set_frame(0);
}

double median_of(std::vector<double> v) { return v.empty() ? 0.0 : median(std::move(v)); }

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
    for (auto& [key, values] : columns) out[key] = median_of(std::move(values));
    return out;
}

std::map<std::string, double> primitives_of(const frame_record& r) {
    std::map<std::string, double> p{{"triangles", double(r.triangles)},
                                    {"shadow_triangles", double(r.shadow_triangles)},
                                    {"points", double(r.points)},
                                    {"lines", double(r.lines)}};
    for (std::size_t i = 1; i < r.instances.size(); ++i)
        p["instances_" + std::string(representation_name(static_cast<representation>(i)))] = double(r.instances[i]);
    return p;
}

bool stop_requested(const bench_settings& settings) { return settings.stop && settings.stop(); }

void save_frame(const image_rgba8& image, const std::filesystem::path& dir, std::uint32_t frame) {
    std::filesystem::create_directories(dir);
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%04u.png", frame);
    write_image(image, dir / name);
}

reference_frames render_reference(const scenario& s, const std::string& family, render::gl_context& context,
                                  bake_cache* cache, const bench_settings& settings, std::size_t configurations) {
    bench_configuration_spec spec;
    spec.options.geometry = geometry_mode::full;
    spec.options.lighting = reference_lighting(s, family);
    spec.samples = k_bench_reference_samples;
    scenario_player player(configured(s, spec), settings.threads, &context, cache,
                           configuration_options(spec, settings));
    warm_up(player);
    const std::string folder = spec.options.lighting.empty() ? "_reference" : "_reference_" + family;
    reference_frames ref;
    for (std::uint32_t f = 0; f < s.frames; ++f) {
        if (settings.progress)
            settings.progress({-1, configurations, 0, settings.timing_rounds, f, s.frames, family});
        const frame_record record = player.step();
        ref.frame_ms.push_back(record.frame_ms);
        ref.images.push_back(box_downsample(player.capture(), spec.samples));
        if (!settings.frames_dir.empty()) save_frame(ref.images.back(), settings.frames_dir / folder, f);
        const std::vector<std::uint32_t> ids = player.capture_plant_ids(spec.samples);
        ref.masks.push_back(plant_mask(ids));
        ref.colors.push_back(mean_plant_colors(ref.images.back(), ids));
        if (stop_requested(settings)) break;
    }
    return ref;
}

// One timing round after round 0 (bench_settings::timing_rounds): `spec` plays the same frames
// after the same warm-up, each read back with its IDs as in round 0 so the device syncs at the
// same points, and nothing else is computed. Returns the frame times.
std::vector<double> time_configuration(const scenario& s, const bench_configuration_spec& spec,
                                       render::gl_context& context, bake_cache* cache,
                                       const bench_settings& settings, bench_progress progress) {
    scenario_player player(configured(s, spec), settings.threads, &context, cache,
                           configuration_options(spec, settings));
    warm_up(player);
    std::vector<double> frame_ms;
    for (std::uint32_t f = 0; f < s.frames; ++f) {
        progress.frame = f;
        if (settings.progress) settings.progress(progress);
        frame_ms.push_back(player.step().frame_ms);
        (void)player.capture();
        (void)player.capture_plant_ids(spec.samples);
        if (stop_requested(settings)) break;
    }
    return frame_ms;
}

// Folds the later timing rounds into `c`: medians, extremes and round medians over every
// round's frames (round 0's are `c`'s own).
void add_timing_rounds(bench_configuration& c, std::vector<double> round0_frame_ms,
                       const std::vector<std::vector<double>>& later_rounds) {
    std::vector<double> all = std::move(round0_frame_ms);
    for (const auto& round : later_rounds) {
        c.frame_ms_rounds.push_back(median_of(round));
        all.insert(all.end(), round.begin(), round.end());
    }
    if (all.empty()) return;
    c.frame_ms_median = median_of(all);
    c.frame_ms_min = *std::min_element(all.begin(), all.end());
    c.frame_ms_max = *std::max_element(all.begin(), all.end());
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

// Round 0 of `spec`: its errors against `ref` and its time; `frame_ms` receives the frame times.
bench_configuration run_configuration(const scenario& s, const bench_configuration_spec& spec,
                                      const reference_frames& ref, render::gl_context& context,
                                      bake_cache* cache, const bench_settings& settings, int index,
                                      std::size_t count, std::vector<double>& frame_ms) {
    reset_peak_resident();
    const player_options options = configuration_options(spec, settings);
    scenario_player player(configured(s, spec), settings.threads, &context, cache, options);
    std::map<std::string, double> out_costs;
    if (options.policy.uses_point_lines()) {
        const primitive_costs& costs = player.costs();
        out_costs = {{"triangle", costs.triangle}, {"point", costs.point}, {"line", costs.line}};
    }
    warm_up(player);
    bench_configuration out;
    out.primitive_costs = std::move(out_costs);
    out.name = spec.name;
    out.family = spec.family;
    out.lighting = lighting_family(s, spec.options.lighting);
    out.description = spec.description;
    out.quality = spec.quality;
    out.frames = s.frames;

    error_accumulator errors;
    frame_ms.clear();
    std::vector<double> upload;
    std::vector<std::map<std::string, double>> cpu, gpu, primitives;
    image_rgba8 previous_image;
    std::vector<plant_colors> colors;
    std::vector<drawn_mix> mixes;
    transition_finder transitions(player.world().table<lod_state>().size());
    for (std::uint32_t f = 0; f < s.frames; ++f) {
        if (settings.progress) settings.progress({index, count, 0, settings.timing_rounds, f, s.frames, {}});
        const frame_record record = player.step();
        frame_ms.push_back(record.frame_ms);
        upload.push_back(double(record.upload_bytes));
        std::map<std::string, double> systems{{"total", record.cpu_ms}};
        for (const auto& [name, ms] : record.systems) systems[name] = ms;
        cpu.push_back(std::move(systems));
        std::map<std::string, double> passes{{"total", record.gpu_ms}};
        for (const auto& [name, ms] : record.passes) passes[name] = ms;
        gpu.push_back(std::move(passes));
        primitives.push_back(primitives_of(record));
        read_drawn_mixes(player.world(), mixes);
        transitions.add_frame(mixes);

        const image_rgba8 image = box_downsample(player.capture(), spec.samples);
        const std::vector<std::uint32_t> ids = player.capture_plant_ids(spec.samples);
        if (!settings.frames_dir.empty()) save_frame(image, settings.frames_dir / spec.name, f);
        const image_rgba8& reference = ref.images[f];
        // The metrics are independent of each other; running them side by side changes no
        // value, only the time the bench takes. (Not tbb::parallel_invoke: its tasks read the
        // functors through references before TSan can be told of the hand-off, ecs/parallel.h.)
        double e_rmse = 0.0, e_ssim = 0.0, e_flip = 0.0;
        ecs::parallel_for_each_index(3, [&](std::size_t metric) {
            if (metric == 0) e_rmse = rmse(reference, image);
            if (metric == 1) e_ssim = mean_ssim(reference, image);
            if (metric == 2) e_flip = flip_error(reference, image, k_bench_flip_pixels_per_degree);
        });
        errors.squared_error += e_rmse * e_rmse;
        errors.ssim += e_ssim;
        errors.perceptual += e_flip;
        errors.coverage_iou += coverage_iou(ref.masks[f], plant_mask(ids));
        ++errors.frames;
        colors.push_back(mean_plant_colors(image, ids));
        if (f > 0) {
            errors.popping += popping_score(image, previous_image, reference, ref.images[f - 1]);
            ++errors.popping_frames;
        }
        previous_image = image;
        if (stop_requested(settings)) break;
    }
    out.frames = std::uint32_t(frame_ms.size());
    out.frame_ms_median = median_of(frame_ms);
    out.frame_ms_min = frame_ms.empty() ? 0.0 : *std::min_element(frame_ms.begin(), frame_ms.end());
    out.frame_ms_max = frame_ms.empty() ? 0.0 : *std::max_element(frame_ms.begin(), frame_ms.end());
    out.frame_ms_rounds = {out.frame_ms_median};
    out.cpu_ms = medians(cpu);
    out.gpu_ms = medians(gpu);
    out.primitives = medians(primitives);
    out.upload_bytes = median_of(upload);
    out.peak_memory_mb = peak_resident_mb();
    out.error = errors.result();
    add_transitions(out.error, transitions, colors, ref);
    return out;
}

std::vector<const bench_configuration_spec*> select(const std::vector<bench_configuration_spec>& configurations,
                                                    const std::vector<std::string>& only) {
    for (const auto& name : only)
        if (std::none_of(configurations.begin(), configurations.end(), [&](const auto& c) { return c.name == name; })) {
            std::string known;
            for (const auto& c : configurations) known += (known.empty() ? "" : ", ") + c.name;
            throw std::invalid_argument("--only: no configuration named '" + name + "' (known: " + known + ")");
        }
    std::vector<const bench_configuration_spec*> selected;
    for (const auto& c : configurations)
        if (only.empty() || std::find(only.begin(), only.end(), c.name) != only.end()) selected.push_back(&c);
    return selected;
}

// Ratios to the baseline of each configuration's lighting family, round by round, for
// configurations timed in as many rounds as it (not the reference: its one round says nothing
// about drift).
void add_baseline_ratios(bench_report& report) {
    for (auto& c : report.configurations) {
        const bench_configuration* baseline = bench_format::family_baseline(report, c.lighting);
        if (!baseline || c.frame_ms_rounds.size() != baseline->frame_ms_rounds.size()) continue;
        c.frame_ms_vs_baseline = bench_format::time_ratio(c, *baseline);
    }
}

}  // namespace

std::string lighting_family(const scenario& s, const std::string& lighting) {
    if (lighting == "sh") return "sh";
    if (lighting == "normal_mapped" || lighting == "pre_lit") return "normal";
    const std::size_t sh = sh_species(s);
    if (sh == s.species.size() && sh > 0) return "sh";
    if (sh == 0) return "normal";
    return "scenario";
}

bench_report run_bench(const scenario& s, const std::vector<bench_configuration_spec>& configurations,
                       render::gl_context& context, bake_cache* cache, bench_settings settings) {
    const std::vector<const bench_configuration_spec*> selected = select(configurations, settings.only);
    bench_report report;
    report.scenario = s.name;
    report.source = s.source;
    report.machine = describe_machine();
    report.gl_renderer = context.renderer();
    report.width = s.width;
    report.height = s.height;
    report.frames = s.frames;
    settings.timing_rounds = std::max(1u, settings.timing_rounds);
    report.timing_rounds = settings.timing_rounds;
    report.reference_samples_per_pixel = k_bench_reference_samples * k_bench_reference_samples;
    report.threads = settings.threads > 0 ? settings.threads : int(std::max(1u, std::thread::hardware_concurrency()));

    // Round 0: each lighting family's reference when its first configuration needs it, then
    // the configuration's errors against it. An interrupt (bench_settings::stop) ends the bench
    // after the frame in progress: what was measured is kept, and the report is partial.
    std::map<std::string, reference_frames> references;
    std::vector<std::vector<double>> round0_frame_ms(selected.size());
    for (std::size_t i = 0; i < selected.size() && !report.partial; ++i) {
        const std::string family = lighting_family(s, selected[i]->options.lighting);
        if (!references.contains(family)) {
            references.emplace(family, render_reference(s, family, context, cache, settings, selected.size()));
            report.lighting_families.push_back(
                {family, family_description(family), median_of(references.at(family).frame_ms)});
            if ((report.partial = stop_requested(settings))) break;  // a reference cut short
        }
        report.configurations.push_back(run_configuration(s, *selected[i], references.at(family), context, cache,
                                                          settings, int(i), selected.size(), round0_frame_ms[i]));
        report.partial = stop_requested(settings);
    }
    // Later timing rounds visit the configurations forwards and backwards in turn, so drift
    // over the run weighs on each about equally. The reference's replay is a check of the
    // comparison, not a configuration to time: it keeps its one round (at 3x3 samples of full
    // geometry it would cost more than all the others).
    std::vector<std::vector<std::vector<double>>> later_rounds(selected.size());
    for (std::uint32_t round = 1; round < report.timing_rounds; ++round)
        for (std::size_t n = 0; n < selected.size(); ++n) {
            const std::size_t i = round % 2 ? selected.size() - 1 - n : n;
            if (selected[i]->family == k_family_reference || i >= report.configurations.size()) continue;
            if ((report.partial = report.partial || stop_requested(settings))) break;
            later_rounds[i].push_back(time_configuration(
                s, *selected[i], context, cache, settings,
                {int(i), selected.size(), round, report.timing_rounds, 0, s.frames, {}}));
        }
    for (std::size_t i = 0; i < report.configurations.size(); ++i)
        add_timing_rounds(report.configurations[i], std::move(round0_frame_ms[i]), later_rounds[i]);
    add_baseline_ratios(report);
    if (settings.costs)
        report.primitive_costs = {{"triangle", settings.costs->triangle},
                                  {"point", settings.costs->point},
                                  {"line", settings.costs->line}};
    return report;
}

}  // namespace sylva
