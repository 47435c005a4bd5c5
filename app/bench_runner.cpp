#include "app/bench_runner.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "app/bench_format.h"
#include "app/metrics.h"
#include "components/lod_state.h"
#include "measure/image_metrics.h"
#include "measure/temporal_metrics.h"
#include "models/image_ops.h"
#include "models/textures.h"

namespace sylva {
namespace {

// What the configurations are compared against, one entry per frame.
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
    double lighting_jump = 0.0;
    std::uint32_t frames = 0;
    std::uint32_t popping_frames = 0;
    std::uint64_t switches = 0;

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
        e.lighting_jump = switches ? lighting_jump / double(switches) : 0.0;
        e.switches = switches;
        return e;
    }
};

scenario configured(const scenario& s, const bench_configuration_spec& c) {
    scenario out = s;
    out.camera.lod_scale = s.camera.lod_scale * c.lod_scale_factor;
    out.width = s.width * c.samples;
    out.height = s.height * c.samples;
    return out;
}

player_options measured(player_options options) {
    options.id_buffer = true;
    options.scenario_lod = false;  // each configuration draws exactly what it names
    return options;
}

// How the player of configuration `spec` draws: as measured(), with the bench's fixed costs
// when it has them (bench_settings::costs).
player_options configuration_options(const bench_configuration_spec& spec,
                                     const bench_settings& settings) {
    player_options options = measured(spec.options);
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

// `lighting`: as player_options::lighting (empty: the scenario's own).
reference_frames render_reference(const scenario& s, render::gl_context& context, bake_cache* cache,
                                  const bench_settings& settings, std::size_t configurations,
                                  const std::string& lighting = {}) {
    bench_configuration_spec spec;
    spec.options.geometry = geometry_mode::full;
    spec.options.lighting = lighting;
    spec.samples = k_bench_reference_samples;
    scenario_player player(configured(s, spec), settings.threads, &context, cache, measured(spec.options));
    warm_up(player);
    reference_frames ref;
    for (std::uint32_t f = 0; f < s.frames; ++f) {
        if (settings.progress)
            settings.progress({-1, configurations, 0, settings.timing_rounds, f, s.frames});
        const frame_record record = player.step();
        ref.frame_ms.push_back(record.frame_ms);
        ref.images.push_back(box_downsample(player.capture(), spec.samples));
        if (!settings.frames_dir.empty())
            save_frame(
                ref.images.back(),
                settings.frames_dir / (lighting.empty() ? "_reference" : "_reference_" + lighting),
                f);
        const std::vector<std::uint32_t> ids = player.capture_plant_ids(spec.samples);
        ref.masks.push_back(plant_mask(ids));
        ref.colors.push_back(mean_plant_colors(ref.images.back(), ids));
        if (stop_requested(settings)) break;
    }
    return ref;
}

bool enough_pixels(const plant_colors& colors, std::uint32_t id) {
    const auto it = colors.find(id);
    return it != colors.end() && it->second.pixels >= k_lighting_jump_min_pixels;
}

// One timing round after round 0 (bench_settings::timing_rounds): `spec` plays the same frames
// after the same warm-up, each read back with its IDs as in round 0 so the device syncs at the
// same points, and nothing else is computed. Returns the frame times.
std::vector<double> time_configuration(const scenario& s, const bench_configuration_spec& spec,
                                       render::gl_context& context, bake_cache* cache,
                                       const bench_settings& settings, bench_progress progress) {
    const player_options options = configuration_options(spec, settings);
    scenario_player player(configured(s, spec), settings.threads, &context, cache, options);
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
    out.description = spec.description;
    out.quality = spec.quality;
    out.frames = s.frames;

    error_accumulator errors;
    frame_ms.clear();
    std::vector<double> upload;
    std::vector<std::map<std::string, double>> cpu, gpu, primitives;
    image_rgba8 previous_image;
    plant_colors previous_colors;
    for (std::uint32_t f = 0; f < s.frames; ++f) {
        if (settings.progress)
            settings.progress({index, count, 0, settings.timing_rounds, f, s.frames});
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

        const image_rgba8 image = box_downsample(player.capture(), spec.samples);
        const std::vector<std::uint32_t> ids = player.capture_plant_ids(spec.samples);
        if (!settings.frames_dir.empty()) save_frame(image, settings.frames_dir / spec.name, f);
        const image_rgba8& reference = ref.images[f];
        // The metrics are independent of each other; running them side by side changes no
        // result (each is a serial, deterministic computation).
        double e_rmse = 0.0, e_ssim = 0.0, e_flip = 0.0;
        tbb::parallel_invoke([&] { e_rmse = rmse(reference, image); }, [&] { e_ssim = mean_ssim(reference, image); },
                             [&] { e_flip = flip_error(reference, image, k_bench_flip_pixels_per_degree); });
        errors.squared_error += e_rmse * e_rmse;
        errors.ssim += e_ssim;
        errors.perceptual += e_flip;
        errors.coverage_iou += coverage_iou(ref.masks[f], plant_mask(ids));
        ++errors.frames;

        plant_colors colors = mean_plant_colors(image, ids);
        if (f > 0) {
            errors.popping += popping_score(image, previous_image, reference, ref.images[f - 1]);
            ++errors.popping_frames;
            // Plants that changed representation between the previous frame and this one.
            const auto& lod = player.world().table<lod_state>();
            for (std::size_t k = 0; k < lod.size(); ++k) {
                const lod_state& state = lod.data()[k];
                if (state.current == state.previous || state.current == representation::none ||
                    state.previous == representation::none)
                    continue;
                const auto id = std::uint32_t(k + 1);
                if (!enough_pixels(colors, id) || !enough_pixels(previous_colors, id) ||
                    !enough_pixels(ref.colors[f], id) || !enough_pixels(ref.colors[f - 1], id))
                    continue;
                errors.lighting_jump += lighting_jump(previous_colors.at(id), colors.at(id),
                                                      ref.colors[f - 1].at(id), ref.colors[f].at(id));
                ++errors.switches;
            }
        }
        previous_image = image;
        previous_colors = std::move(colors);
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
    return out;
}

bench_configuration_spec mesh_lod(double factor) {
    bench_configuration_spec c;
    std::ostringstream name;
    name << "mesh_lod";
    if (factor != 1.0) name << "_x" << factor;
    c.name = name.str();
    c.family = "mesh_lod";
    std::ostringstream description;
    description << "the runtime's mesh levels (full, reduced, far) by distance";
    if (factor != 1.0) description << ", switch distances x" << factor;
    c.description = description.str();
    c.quality = factor;
    c.lod_scale_factor = float(factor);
    return c;
}

bench_configuration_spec single(representation r, std::string description) {
    bench_configuration_spec c;
    c.name = std::string(representation_name(r)) + "_only";
    c.family = "single_representation";
    c.description = std::move(description);
    c.options.policy = {lod_policy::kind::single, r, r, 0.0f};
    return c;
}

bench_configuration_spec baseline(float distance_m, bool named_baseline) {
    bench_configuration_spec c;
    c.name = named_baseline ? "baseline" : "baseline_" + std::to_string(int(distance_m)) + "m";
    c.family = "baseline";
    c.description = "engine baseline: full mesh nearer than " + std::to_string(int(distance_m)) +
                    " m x plant scale, one crossed-quad billboard beyond, hard switch";
    c.quality = distance_m;
    c.options.policy = {lod_policy::kind::hard_switch, representation::mesh_full, representation::crossed_billboard,
                        distance_m};
    return c;
}

// Deussen 2002: every plant as prefixes of its random-order triangles, points and lines, with
// sample distance d' (pixels); the sweep trades error for time (§5.4). Soft splats, fog-weighted,
// by default; `_opaque` draws the paper's opaque squares, `_uniform` spaces samples d' apart
// however much fog lies between them and the eye (point_line_lod.h fog_sample_distance).
bench_configuration_spec points_lines(float sample_distance_px,
                                      splat_style splats = splat_style::soft,
                                      bool fog_weighted = true) {
    bench_configuration_spec c;
    std::ostringstream name;
    name << "points_lines";
    if (sample_distance_px != 1.0f) name << "_d" << sample_distance_px;
    if (splats == splat_style::opaque) name << "_opaque";
    if (!fog_weighted) name << "_uniform";
    c.name = name.str();
    c.family = "points_lines";
    std::ostringstream description;
    description << "points and lines (Deussen 2002), d' = " << sample_distance_px
                << " px, c_p = 1.3, "
                << (splats == splat_style::soft ? "soft splats" : "opaque splats (the paper's)")
                << (fog_weighted ? ", fog-weighted" : ", d' everywhere (no fog weighting)");
    c.description = description.str();
    c.quality = sample_distance_px;
    c.options.policy.mode = lod_policy::kind::points_lines;
    c.options.policy.points = {sample_distance_px, 1.3f, true, splats, fog_weighted};
    return c;
}

// Behrendt 2005 §2.3: meshes near, billboard clouds from 30 m x plant scale, crossed billboards
// beyond the species' far distance, each switch cross-faded without sorting.
// `lighting`: every species lit as "normal_mapped", "pre_lit" or "sh" (§2.3, §4).
bench_configuration_spec billboard_clouds(const std::string& lighting) {
    bench_configuration_spec c;
    c.name = lighting == "normal_mapped" ? "billboard_clouds" : "billboard_clouds_" + lighting;
    c.family = "billboard_clouds";
    c.description =
        "billboard clouds (Behrendt 2005), " + lighting +
        ": full mesh nearer than 30 m x plant scale, cloud beyond, crossed billboard beyond "
        "the far distance, sort-free fades";
    c.options.policy.mode = lod_policy::kind::billboard_clouds;
    c.options.lighting = lighting;
    return c;
}

// `c` with every species lit by SH transfer (Behrendt 2005 §4), named `<name>_sh`.
bench_configuration_spec lit_by_transfer(bench_configuration_spec c) {
    c.name += "_sh";
    c.description += ", every species lit by SH transfer (Behrendt 2005 §4)";
    c.options.lighting = "sh";
    return c;
}

}  // namespace

std::vector<bench_configuration_spec> default_bench_configurations() {
    std::vector<bench_configuration_spec> list;
    bench_configuration_spec reference;
    reference.name = "reference";
    reference.family = "reference";
    reference.description = "the reference rendered again (full geometry, 3x3 samples): must give zero error";
    reference.options.geometry = geometry_mode::full;
    reference.samples = k_bench_reference_samples;
    list.push_back(reference);

    bench_configuration_spec brute;
    brute.name = "brute_force";
    brute.family = "brute_force";
    brute.description = "every plant at full geometry, one sample per pixel";
    brute.options.geometry = geometry_mode::full;
    list.push_back(brute);

    for (double factor : {1.0, 0.25, 0.5, 2.0}) list.push_back(mesh_lod(factor));
    list.push_back(single(representation::mesh_reduced, "every plant as its reduced mesh"));
    list.push_back(single(representation::mesh_far, "every plant as its far mesh"));
    list.push_back(single(representation::crossed_billboard, "every plant as one crossed-quad billboard"));
    list.push_back(single(representation::billboard_cloud, "every plant as its billboard cloud (Behrendt 2005)"));
    list.push_back(baseline(50.0f, true));
    list.push_back(baseline(25.0f, false));
    list.push_back(baseline(100.0f, false));
    list.push_back(billboard_clouds("normal_mapped"));
    list.push_back(billboard_clouds("pre_lit"));
    list.push_back(billboard_clouds("sh"));
    for (float d : {1.0f, 0.5f, 2.0f, 2.25f, 2.5f, 3.0f, 4.0f}) list.push_back(points_lines(d));
    for (float d : {1.0f, 2.0f}) list.push_back(points_lines(d, splat_style::opaque));
    for (float d : {1.0f, 2.0f, 2.5f, 3.0f}) list.push_back(points_lines(d, splat_style::soft, false));
    // §5.4: d' adapted every frame to hold a budget (the paper's Table 1 draws 10 M triangles
    // with about 1 M primitives).
    bench_configuration_spec budget = points_lines(1.0f);
    budget.name = "points_lines_budget_1m";
    budget.description = "points and lines, d' adapted every frame to 1 M triangle equivalents (Deussen 2002 §5.4)";
    budget.options.budget.primitives = 1e6;
    list.push_back(budget);
    // The same without §6.2's tile sets: every plant drawn on its own, to measure what they do.
    bench_configuration_spec plants_only = points_lines(1.0f);
    plants_only.name = "points_lines_no_tile_sets";
    plants_only.description = "points and lines, d' = 1 px, every plant on its own (no eco-tile point sets, §6.2)";
    plants_only.options.policy.tile_sets = false;
    list.push_back(plants_only);
    // Behrendt 2005 §4: the same representations lit by precomputed radiance transfer.
    list.push_back(lit_by_transfer(mesh_lod(1.0)));
    list.push_back(lit_by_transfer(points_lines(1.0f)));
    return list;
}

bench_report run_bench(const scenario& s, const std::vector<bench_configuration_spec>& configurations,
                       render::gl_context& context, bake_cache* cache, bench_settings settings) {
    std::vector<const bench_configuration_spec*> selected;
    for (const auto& c : configurations)
        if (settings.only.empty() || std::find(settings.only.begin(), settings.only.end(), c.name) != settings.only.end())
            selected.push_back(&c);
    for (const auto& name : settings.only)
        if (std::none_of(configurations.begin(), configurations.end(), [&](const auto& c) { return c.name == name; })) {
            std::string known;
            for (const auto& c : configurations) known += (known.empty() ? "" : ", ") + c.name;
            throw std::invalid_argument("--only: no configuration named '" + name + "' (known: " + known + ")");
        }

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

    const reference_frames ref = render_reference(s, context, cache, settings, selected.size());
    report.partial = stop_requested(settings);
    report.reference_frame_ms_median = median_of(ref.frame_ms);
    // A configuration that lights every species another way is compared with a reference lit
    // that way too (full geometry, 3x3 samples), so its errors are its representation's alone.
    // Full geometry draws no clouds, so pre-lit and normal-mapped references are one image.
    auto reference_lighting = [](const std::string& l) {
        return l == "sh" ? l : std::string("normal_mapped");
    };
    const bool scenario_all_sh =
        std::all_of(s.species.begin(), s.species.end(), [&](const species_settings& sp) {
            return (sp.lighting == "scenario" ? s.lod.lighting : sp.lighting) == "sh";
        });
    const bool scenario_no_sh =
        std::none_of(s.species.begin(), s.species.end(), [&](const species_settings& sp) {
            return (sp.lighting == "scenario" ? s.lod.lighting : sp.lighting) == "sh";
        });
    std::map<std::string, reference_frames> lit_references;
    std::vector<std::vector<double>> round0_frame_ms(selected.size());
    for (std::size_t i = 0; i < selected.size() && !report.partial; ++i) {
        const std::string lighting = selected[i]->options.lighting.empty()
                                         ? std::string()
                                         : reference_lighting(selected[i]->options.lighting);
        const bool own = lighting.empty() || (lighting == "sh" && scenario_all_sh) ||
                         (lighting == "normal_mapped" && scenario_no_sh);
        if (!own && !lit_references.contains(lighting))
            lit_references.emplace(
                lighting, render_reference(s, context, cache, settings, selected.size(), lighting));
        report.configurations.push_back(
            run_configuration(s, *selected[i], own ? ref : lit_references.at(lighting), context,
                              cache, settings, int(i), selected.size(), round0_frame_ms[i]));
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
            if (selected[i]->family == "reference" || i >= report.configurations.size()) continue;
            if ((report.partial = report.partial || stop_requested(settings))) break;
            later_rounds[i].push_back(time_configuration(
                s, *selected[i], context, cache, settings,
                {int(i), selected.size(), round, report.timing_rounds, 0, s.frames}));
        }
    for (std::size_t i = 0; i < report.configurations.size(); ++i)
        add_timing_rounds(report.configurations[i], std::move(round0_frame_ms[i]), later_rounds[i]);
    // Ratios to the baseline round by round, for configurations timed in every round (not the
    // reference: its one round says nothing about drift).
    if (const bench_configuration* baseline = bench_format::find_configuration(report, "baseline"))
        for (auto& c : report.configurations) {
            if (c.frame_ms_rounds.size() != baseline->frame_ms_rounds.size()) continue;
            std::vector<double> ratios;
            for (std::size_t r = 0; r < c.frame_ms_rounds.size(); ++r)
                ratios.push_back(c.frame_ms_rounds[r] / baseline->frame_ms_rounds[r]);
            c.frame_ms_vs_baseline = median_of(std::move(ratios));
        }
    if (settings.costs)
        report.primitive_costs = {{"triangle", settings.costs->triangle},
                                  {"point", settings.costs->point},
                                  {"line", settings.costs->line}};
    return report;
}

double peak_resident_mb() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
    return 0.0;
}

void reset_peak_resident() {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";  // resets VmHWM to the current resident size (Linux 4.0+); ignored elsewhere
}

}  // namespace sylva
