// `sylva play`: plays a scenario and writes every frame and metrics.json.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <spdlog/spdlog.h>

#include "app/commands.h"
#include "app/frame_range.h"
#include "app/run_options.h"
#include "app/interrupt.h"
#include "app/scenario_options.h"
#include "app/scenario_player.h"
#include "models/image/image_ops.h"
#include "models/generate/textures.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

struct play_options {
    scenario_options scenario;
    std::string out_dir = "out";
    std::string format = "png";
    bool headless = false;
    bool reference = false;      // full geometry, k_reference_samples² samples per pixel
    bool full_geometry = false;  // full geometry, one sample per pixel (brute force)
    std::string frame_range;     // "A:B": a shard (app/frame_range.h); empty: every frame
    std::string shard;           // "K/N": the same, as shard K of N
};

// Samples per pixel along each axis in --reference (issue 4 asks for at least 3x3).
constexpr std::uint32_t k_reference_samples = 3;

std::filesystem::path frame_path(const play_options& o, std::uint64_t frame) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%04llu.%s", static_cast<unsigned long long>(frame),
                  o.format.c_str());
    return std::filesystem::path(o.out_dir) / name;
}

// Plays the frames of `range`, stopping after the current one when interrupted
// (app/interrupt.h).
void play_frames(scenario_player& player, const play_options& o, frame_range range, std::uint32_t samples,
                 std::vector<frame_record>& frames) {
    for (std::uint32_t f = range.first; f < range.end && !interrupt_requested(); ++f) {
        frame_record record = player.step();
        const image_rgba8 image = box_downsample(player.capture(), samples);
        record.image_hash = fnv1a(image.texels.data(), image.texels.size());
        write_image(image, frame_path(o, record.frame));
        // "frame N/M" counts this run's frames (tests and scripts wait for it); a shard adds the
        // frame's number on the path.
        std::fprintf(stderr, "\r[sylva] frame %u/%u%s  %.1f ms (cpu %.1f, gpu %.1f)  %llu triangles   ",
                     f - range.first + 1, range.count(),
                     range.first > 0 ? (" (path frame " + std::to_string(f) + ")").c_str() : "", record.frame_ms,
                     record.cpu_ms, record.gpu_ms, static_cast<unsigned long long>(record.triangles));
        frames.push_back(std::move(record));
    }
    std::fprintf(stderr, "\n");
}

int play(const play_options& o) {
    const std::optional<scenario> loaded = load_or_report(o.scenario);
    if (!loaded) return k_exit_bad_input;
    scenario s = *loaded;
    frame_range range{0, s.frames};
    try {
        range = range_asked(o.frame_range, o.shard, s.frames);
    } catch (const std::invalid_argument& e) {
        spdlog::error("{}", e.what());
        return k_exit_bad_input;
    }
    const std::uint32_t samples = o.reference ? k_reference_samples : 1;
    s.width *= samples;  // the reference renders supersampled and resolves with a box filter
    s.height *= samples;
    const geometry_mode mode = o.reference || o.full_geometry ? geometry_mode::full : geometry_mode::lod;
    render::context_options context_options;
    context_options.width = int(s.width);
    context_options.height = int(s.height);
    context_options.headless = o.headless || !render::display_available();
    const interrupt_guard interrupts;
    std::vector<frame_record> frames;  // the frames written so far
    try {
        auto context = render::create_context(context_options);
        spdlog::info("playing '{}' ({}): {} frames at {}x{} on {} ({})", s.name, s.source, s.frames,
                     s.width, s.height, context->renderer(), context->backend_name());
        bake_cache cache;
        // Every file the scenario names is read here, before the output folder exists: a bad one
        // is bad input (exit 2) with nothing written.
        scenario_player player(s, o.scenario.threads, context.get(), &cache, mode);
        if (const std::string why = player.unreproducible_reason(); !why.empty() && range.count() != s.frames) {
            spdlog::error("{} {}: {}, so no two runs of it are equal and a shard cannot equal the whole run; play it "
                          "whole",
                          o.shard.empty() ? "--frame-range" : "--shard", o.shard.empty() ? o.frame_range : o.shard, why);
            return k_exit_bad_input;
        }
        std::error_code ec;
        std::filesystem::create_directories(o.out_dir, ec);
        if (ec) {
            spdlog::error("cannot create the output folder {}: {}", o.out_dir, ec.message());
            return k_exit_bad_input;
        }
        run_info info = player.info();
        info.width /= samples;
        info.height /= samples;
        info.mode = o.reference ? "reference" : (o.full_geometry ? "full_geometry" : "lod");
        info.samples_per_pixel = samples * samples;
        info.frames_planned = range.count();
        info.options = run_options();
        info.selection_inputs_hash = player.selection_inputs_hash();
        info.frame_range = {range.first, range.end};
        info.path_frames = s.frames;
        spdlog::info("{} plants, {} source triangles, set up in {:.0f} ms, {} threads", info.plants,
                     info.source_triangles, info.setup_ms, info.threads);
        if (range.first > 0) {
            spdlog::info("reaching frame {} (the shard {} of {} frames)", range.first, to_string(range), s.frames);
            // Ctrl-C during the replay ends it there; no frame of the shard is then played.
            const replay_cost cost = player.replay_to(range.first, {}, {}, interrupt_requested);
            info.replay_cpu_frames = cost.cpu_frames;
            info.replay_rendered_frames = cost.rendered_frames;
            info.replay_ms = cost.ms;
            spdlog::info("reached frame {} in {:.0f} ms: {} frames' systems alone, {} rendered", range.first,
                         cost.ms, cost.cpu_frames, cost.rendered_frames);
        }
        play_frames(player, o, range, samples, frames);
        const std::size_t written = frames.size();
        info.partial = interrupt_requested();
        info.interrupted_by = interrupt_signal_name();
        const auto metrics = std::filesystem::path(o.out_dir) / "metrics.json";
        write_metrics_json(metrics, info, frames);
        std::vector<double> frame_ms;
        for (const auto& f : frames) frame_ms.push_back(f.frame_ms);
        if (info.partial) {
            spdlog::warn("interrupted by {}: wrote {} of {} frames and {} (marked partial)",
                         info.interrupted_by, written, range.count(), metrics.string());
            return interrupt_exit_code();
        }
        spdlog::info("wrote {} frames and {} (median frame {:.1f} ms)", written, metrics.string(),
                     median(frame_ms));
    } catch (const scenario_error& e) {
        spdlog::error("{}", e.what());
        return k_exit_bad_input;
    } catch (const std::exception& e) {
        spdlog::error("{}", e.what());
        if (!frames.empty())
            spdlog::error("partial output: {} frames in {} and no metrics.json", frames.size(),
                          o.out_dir);
        return k_exit_failure;
    }
    return k_exit_ok;
}

}  // namespace

command_runner add_play_command(CLI::App& app) {
    auto options = std::make_shared<play_options>();
    add_scenario_options(app, options->scenario);
    app.add_option("--out", options->out_dir, "Output folder for frame_NNNN images and metrics.json")
        ->capture_default_str();
    app.add_option("--format", options->format, "Frame image format: png or exr (through OpenImageIO)")
        ->check(CLI::IsMember({"png", "exr"}))
        ->capture_default_str();
    auto* reference = app.add_flag(
        "--reference", options->reference,
        "Reference rendering: every plant at full geometry in every pass (no LOD, no distance "
        "culling), 3x3 samples per pixel box-filtered down, same lighting and shadows");
    app.add_flag("--full-geometry", options->full_geometry,
                 "Brute force: every plant at full geometry, one sample per pixel")
        ->excludes(reference);
    app.add_option("--frame-range", options->frame_range,
                   "Play only frames FIRST to END - 1 of the camera path (FIRST:END; FIRST: runs to the "
                   "end), exactly as a whole run plays them: the frames before are replayed without "
                   "rendering to reach FIRST's state. `sylva merge` joins shards into the whole run's "
                   "output; `sylva farm` runs them as a Slurm array job")
        ->type_name("FIRST:END");
    app.add_option("--shard", options->shard,
                   "The same as shard K (from 0) of N: N contiguous frame ranges, the first ones a frame "
                   "longer when N does not divide the path (what `sylva farm`'s array tasks pass)")
        ->type_name("K/N");
    app.add_flag("--headless", options->headless,
                 "Render offscreen with OSMesa even when a display is available (the default "
                 "without a display)");
    return [options] { return play(*options); };
}

}  // namespace sylva
