#include "app/bench_runner.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <thread>

#include "app/bench_format.h"
#include "app/bench_measurements.h"
#include "app/metrics.h"
#include "app/process_memory.h"
#include "components/lod_state.h"
#include "models/generate/textures.h"
#include "models/image/image_ops.h"

namespace sylva {
namespace {

// What every player of one bench shares: the scenario, where it draws, and how.
struct bench_run {
    const scenario& s;
    render::gl_context& context;
    bake_cache* cache;
    const bench_settings& settings;
    std::size_t configurations;  // how many were selected, for the progress
    frame_range range;           // the frames measured: the path's, or a shard's
};

// The scenario as configuration `spec` changes it: its LOD scale and samples per pixel.
scenario scenario_of(const bench_run& run, const bench_configuration_spec& spec) {
    scenario s = run.s;
    s.camera.lod_scale = run.s.camera.lod_scale * spec.lod_scale_factor;
    s.width = run.s.width * spec.samples;
    s.height = run.s.height * spec.samples;
    return s;
}

// The player of configuration `spec`: the scenario as `spec` changes it, drawn with exactly
// what `spec` names (not the scenario's lod section), with an ID buffer, and with the bench's
// fixed costs when it has them.
scenario_player make_player(const bench_run& run, const bench_configuration_spec& spec) {
    scenario s = scenario_of(run, spec);
    player_options options = spec.options;
    options.id_buffer = true;
    options.scenario_lod = false;
    if (run.settings.costs) {
        options.costs = *run.settings.costs;
        options.measure_costs = false;
    }
    return scenario_player(std::move(s), run.settings.threads, &run.context, run.cache, options);
}

// Plays frame 0 once and rewinds, so shader compilation and first-use allocation are not timed
// (each configuration has its own renderer). Playback is a function of the frame number, and
// the rewound player forgets the frame it showed, so the frames that follow are the same as
// without it.
void warm_up(scenario_player& player) {
    player.step();
    player.set_frame(0);
    player.forget_shown_frame();
}

bool stop_requested(const bench_settings& settings) { return settings.stop && settings.stop(); }

// Plays the scenario's frames, reporting `progress` before each and handing each frame's record
// to `on_frame`; stops after the frame in progress when asked to (bench_settings::stop).
template <class F>
void play_frames(const bench_run& run, scenario_player& player, bench_progress progress, F&& on_frame) {
    for (std::uint32_t f = run.range.first; f < run.range.end; ++f) {
        progress.frame = f - run.range.first;
        if (run.settings.progress) run.settings.progress(progress);
        on_frame(f, player.step());
        if (stop_requested(run.settings)) break;
    }
}

// A played frame resolved to the output size, with its plant IDs at the same size.
struct resolved_frame {
    image_rgba8 image;
    std::vector<std::uint32_t> ids;
};

// Reads frame `frame` back from `player`, writing it as dir/frame_NNNN.png when the bench
// writes frames (bench_settings::frames_dir).
resolved_frame resolve(const bench_run& run, scenario_player& player, std::uint32_t samples,
                       const std::string& dir, std::uint32_t frame) {
    resolved_frame out{box_downsample(player.capture(), samples), player.capture_plant_ids(samples)};
    if (!run.settings.frames_dir.empty()) {
        const std::filesystem::path folder = run.settings.frames_dir / dir;
        std::filesystem::create_directories(folder);
        char name[32];
        std::snprintf(name, sizeof(name), "frame_%04u.png", frame);
        write_image(out.image, folder / name);
    }
    return out;
}

// The reference of lighting family `family` for the frames measured, and for a shard the frame
// before them (popping compares each frame with the one before). Full geometry carries no state
// over frames but the frame before's (every plant drawn whole, no selection, fades or budgets),
// so a shard's reference plays only that frame before its own (scenario_player::replay_to).
reference_frames render_reference(const bench_run& run, const std::string& family, double& replay_ms) {
    const bench_configuration_spec spec = reference_configuration(run.s, family);
    scenario_player player = make_player(run, spec);
    warm_up(player);
    const std::string folder = spec.options.lighting.empty() ? "_reference" : "_reference_" + family;
    reference_frames ref;
    if (run.range.first > 0) {
        replay_ms += player.replay_to(run.range.first, {}, [&](const frame_record& record, bool rendered) {
                               if (rendered)
                                   ref.add_frame(std::uint32_t(record.frame), box_downsample(player.capture(), spec.samples),
                                                 player.capture_plant_ids(spec.samples));
                           }).ms;
    }
    play_frames(run, player, {-1, run.configurations, 0, run.settings.timing_rounds, 0, run.range.count(), family},
                [&](std::uint32_t f, const frame_record& record) {
                    resolved_frame frame = resolve(run, player, spec.samples, folder, f);
                    ref.frame_ms.push_back(record.frame_ms);
                    ref.add_frame(f, std::move(frame.image), frame.ids);
                });
    return ref;
}

// The reference's colours of frames before a shard that its configurations' transitions began
// in (a fresh player: the reference carries nothing over frames).
void add_reference_colors(const bench_run& run, const std::string& family, const std::vector<std::uint32_t>& frames,
                          reference_frames& ref) {
    if (frames.empty()) return;
    const bench_configuration_spec spec = reference_configuration(run.s, family);
    scenario_player player = make_player(run, spec);
    for (const std::uint32_t f : frames) {
        player.set_frame(f);
        player.step();
        ref.add_colors(f, box_downsample(player.capture(), spec.samples), player.capture_plant_ids(spec.samples));
    }
}

// One timing round after round 0 (bench_settings::timing_rounds): `spec` plays the same frames
// after the same warm-up, each read back with its IDs as in round 0 so the device syncs at the
// same points, and nothing else is computed. Returns the frame times.
std::vector<double> time_configuration(const bench_run& run, const bench_configuration_spec& spec,
                                       const bench_progress& progress, double& replay_ms) {
    scenario_player player = make_player(run, spec);
    warm_up(player);
    if (run.range.first > 0) replay_ms += player.replay_to(run.range.first).ms;
    std::vector<double> frame_ms;
    play_frames(run, player, progress, [&](std::uint32_t, const frame_record& record) {
        frame_ms.push_back(record.frame_ms);
        (void)player.capture();
        (void)player.capture_plant_ids(spec.samples);
    });
    return frame_ms;
}

// The frames before a shard that `spec`'s transitions still open at its first frame began in:
// found by a player that runs the frame's systems alone (no GL) with the same options and the
// measuring player's costs, so the measuring player renders only those. Its state is checked
// against the measuring player's frame by frame (`state_hashes`).
std::vector<std::uint32_t> plan_replay(const bench_run& run, const bench_configuration_spec& spec,
                                       const scenario_player& measuring, std::vector<std::uint64_t>& state_hashes) {
    scenario s = scenario_of(run, spec);
    player_options options = spec.options;
    options.scenario_lod = false;
    options.costs = measuring.costs();
    options.measure_costs = false;
    options.assets = std::make_shared<scene_assets>(measuring.assets_as_built());
    scenario_player planner(std::move(s), run.settings.threads, nullptr, nullptr, options);
    warm_up(planner);
    configuration_measurements found(planner.world().table<lod_state>().size(), run.range.first, run.range.end,
                                     run.s.frames);
    state_hashes.assign(run.range.first, 0);
    planner.replay_to(run.range.first, {}, [&](const frame_record& record, bool) {
        state_hashes[record.frame] = record.state_hash;
        found.add_replayed_frame(std::uint32_t(record.frame), planner.world(), nullptr, nullptr);
    });
    return found.open_transition_starts();
}

// Round 0 of `spec` for the frames measured: its per-frame errors against `ref` and its time,
// into `out`; its transitions are measured later (finish_configuration), once the reference
// has the colours of the frames before a shard they began in (`wanted`).
configuration_measurements run_configuration(const bench_run& run, const bench_configuration_spec& spec,
                                             const reference_frames& ref, int index, bench_configuration& out,
                                             std::vector<std::uint32_t>& wanted, double& replay_ms) {
    reset_peak_resident();
    scenario_player player = make_player(run, spec);
    if (spec.options.policy.uses_point_lines()) out.primitive_costs = cost_map(player.costs());
    out.selection_inputs_hash = player.selection_inputs_hash();
    warm_up(player);
    out.name = spec.name;
    out.family = spec.family;
    out.lighting = lighting_family(run.s, spec.options.lighting);
    out.description = spec.description;
    out.quality = spec.quality;

    configuration_measurements measured(player.world().table<lod_state>().size(), run.range.first, run.range.end,
                                        run.s.frames);
    if (run.range.first > 0) {
        std::vector<std::uint64_t> planned_hashes;
        std::vector<std::uint32_t> starts;
        // Nothing to plan where the replay renders every frame (the auto ladder) or carries nothing
        // over (full geometry: the reference's replay check).
        if (!player.replay_renders_every_frame() && spec.options.geometry != geometry_mode::full)
            starts = plan_replay(run, spec, player, planned_hashes);
        const auto render_frame = [&](std::uint64_t f) {
            return std::binary_search(starts.begin(), starts.end(), std::uint32_t(f));
        };
        replay_ms += player.replay_to(run.range.first, render_frame, [&](const frame_record& record, bool rendered) {
            const auto f = std::uint32_t(record.frame);
            if (f < planned_hashes.size() && planned_hashes[f] != 0 && planned_hashes[f] != record.state_hash)
                throw std::logic_error("bench shard: configuration " + spec.name + " replayed without GL differs at frame " +
                                       std::to_string(f) + " from its replay with GL");
            if (!rendered) return measured.add_replayed_frame(f, player.world(), nullptr, nullptr);
            const resolved_frame frame{box_downsample(player.capture(), spec.samples),
                                       player.capture_plant_ids(spec.samples)};
            measured.add_replayed_frame(f, player.world(), &frame.image, &frame.ids);
        }).ms;
        wanted = measured.open_transition_starts();
    }
    play_frames(run, player, {index, run.configurations, 0, run.settings.timing_rounds, 0, run.range.count(), {}},
                [&](std::uint32_t f, const frame_record& record) {
                    resolved_frame frame = resolve(run, player, spec.samples, spec.name, f);
                    measured.add_frame(f, record, player.world(), std::move(frame.image), frame.ids, ref);
                });
    out.peak_memory_mb = peak_resident_mb();
    return measured;
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

}  // namespace

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
    const frame_range range = settings.range.value_or(frame_range{0, s.frames});
    if (range.end > s.frames || range.first >= range.end)
        throw std::invalid_argument("bench: frames " + to_string(range) + " are not within the path's " +
                                    std::to_string(s.frames));
    report.frames = range.count();
    report.path_frames = s.frames;
    report.range = {range.first, range.end, host_name(), report.machine, report.threads, 0.0};
    if (range.count() != s.frames)
        for (const bench_configuration_spec* spec : selected) {
            const player_options& o = spec->options;
            const bool timed_ladder = o.target_frame_ms > 0.0 && !(o.max_error > 0.0);
            const bool timed_points = o.policy.uses_point_lines() && o.budget.frame_ms > 0.0 && !(o.budget.primitives > 0.0);
            if (timed_ladder || timed_points)
                throw std::invalid_argument("bench frames " + to_string(range) + ": configuration " + spec->name +
                                            " holds a frame-time target, adapting to the device's measured time, so "
                                            "no two runs of it are equal and no shard can equal the whole bench; "
                                            "leave it out (--only) or bench it whole");
        }
    const bench_run run{s, context, cache, settings, selected.size(), range};

    // Round 0: each lighting family's reference when its first configuration needs it, then
    // the configuration's errors against it. An interrupt (bench_settings::stop) ends the bench
    // after the frame in progress: what was measured is kept, and the report is partial.
    std::map<std::string, reference_frames> references;
    std::vector<configuration_measurements> measured;
    std::map<std::string, std::vector<std::uint32_t>> wanted_colors;  // per family, before a shard
    double& replay_ms = report.range.replay_ms;
    for (std::size_t i = 0; i < selected.size() && !report.partial; ++i) {
        const std::string family = lighting_family(s, selected[i]->options.lighting);
        if (!references.contains(family)) {
            references.emplace(family, render_reference(run, family, replay_ms));
            const std::vector<double>& ms = references.at(family).frame_ms;
            report.lighting_families.push_back({family, lighting_family_description(family), median(ms), ms});
            if ((report.partial = stop_requested(settings))) break;  // a reference cut short
        }
        report.configurations.emplace_back();
        std::vector<std::uint32_t> wanted;
        measured.push_back(run_configuration(run, *selected[i], references.at(family), int(i),
                                             report.configurations.back(), wanted, replay_ms));
        for (const std::uint32_t f : wanted)
            if (f + 1 < range.first) wanted_colors[family].push_back(f);  // range.first - 1 is rendered
        report.partial = stop_requested(settings);
    }
    // A shard's transitions that began before it are measured against the reference's colours
    // of their first frames, then every configuration's figures are summed up.
    for (auto& [family, frames] : wanted_colors) {
        std::sort(frames.begin(), frames.end());
        frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
        add_reference_colors(run, family, frames, references.at(family));
    }
    for (std::size_t i = 0; i < report.configurations.size(); ++i)
        measured[i].summarize(report.configurations[i], references.at(report.configurations[i].lighting));
    measured.clear();
    // Later timing rounds visit the configurations forwards and backwards in turn, so drift
    // over the run weighs on each about equally. The reference's replay is a check of the
    // comparison, not a configuration to time: it keeps its one round (at 3x3 samples of full
    // geometry it would cost more than all the others).
    for (std::uint32_t round = 1; round < report.timing_rounds; ++round)
        for (std::size_t n = 0; n < selected.size(); ++n) {
            const std::size_t i = round % 2 ? selected.size() - 1 - n : n;
            if (selected[i]->family == k_family_reference || i >= report.configurations.size()) continue;
            if ((report.partial = report.partial || stop_requested(settings))) break;
            add_timing_round(report.configurations[i],
                             time_configuration(run, *selected[i],
                                                {int(i), selected.size(), round, report.timing_rounds, 0,
                                                 range.count(), {}},
                                                replay_ms));
        }
    for (bench_configuration& c : report.configurations) summarize_records(c);
    add_baseline_ratios(report);
    if (settings.costs) report.primitive_costs = cost_map(*settings.costs);
    return report;
}

}  // namespace sylva
