#include "app/shard_merge.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <stdexcept>

#include "app/bench_measurements.h"
#include "app/bench_report.h"
#include "app/metrics.h"
#include "app/run_options.h"

namespace sylva {
namespace {

std::string range_text(const std::array<std::uint64_t, 2>& r) {
    return std::to_string(r[0]) + ":" + std::to_string(r[1]);
}

struct play_shard {
    std::filesystem::path dir;
    metrics_file metrics;
};

// What must be equal in every shard of one run, with its name for the error message.
void require_same(const play_shard& a, const play_shard& b) {
    const run_info& x = a.metrics.info;
    const run_info& y = b.metrics.info;
    const auto check = [&](bool same, const std::string& what, const std::string& xs, const std::string& ys) {
        if (!same)
            throw std::invalid_argument("shards " + a.dir.string() + " and " + b.dir.string() + " are not of one run: " +
                                        what + " " + xs + " against " + ys);
    };
    check(x.scenario == y.scenario, "scenario", x.scenario, y.scenario);
    check(x.source == y.source, "scenario file", x.source, y.source);
    check(x.mode == y.mode, "mode", x.mode, y.mode);
    check(x.width == y.width && x.height == y.height, "size", std::to_string(x.width) + "x" + std::to_string(x.height),
          std::to_string(y.width) + "x" + std::to_string(y.height));
    check(x.samples_per_pixel == y.samples_per_pixel, "samples per pixel", std::to_string(x.samples_per_pixel),
          std::to_string(y.samples_per_pixel));
    check(x.plants == y.plants, "plants", std::to_string(x.plants), std::to_string(y.plants));
    check(x.source_triangles == y.source_triangles, "source triangles", std::to_string(x.source_triangles),
          std::to_string(y.source_triangles));
    check(x.path_frames == y.path_frames, "camera path frames", std::to_string(x.path_frames),
          std::to_string(y.path_frames));
    // Another rasteriser draws other pixels: its frames are not this run's.
    check(x.gl_renderer == y.gl_renderer && x.gl_version == y.gl_version, "renderer",
          x.gl_renderer + " " + x.gl_version, y.gl_renderer + " " + y.gl_version);
    check(x.options == y.options, "options", run_options_text(x.options), run_options_text(y.options));
    check(x.selection_inputs_hash == y.selection_inputs_hash,
          "device costs and rung tables (measured on different kinds of node? give every node the bake job's "
          "cache, or run the shards on one kind): hash",
          std::to_string(x.selection_inputs_hash), std::to_string(y.selection_inputs_hash));
    check(x.static_upload_bytes == y.static_upload_bytes, "static upload bytes", std::to_string(x.static_upload_bytes),
          std::to_string(y.static_upload_bytes));
}

// The frame image format the run wrote (play --format; png unless the options say).
std::string frame_format(const std::vector<std::string>& options) {
    for (std::size_t i = 0; i < options.size(); ++i) {
        if (options[i] == "--format" && i + 1 < options.size()) return options[i + 1];
        if (options[i].rfind("--format=", 0) == 0) return options[i].substr(9);
    }
    return "png";
}

// Links `from` as `to` where they share a file system (a thousand 4K frames are not copied),
// else copies it.
void link_or_copy(const std::filesystem::path& from, const std::filesystem::path& to) {
    std::filesystem::remove(to);
    std::error_code linked;
    std::filesystem::create_hard_link(from, to, linked);
    if (linked) std::filesystem::copy_file(from, to);
}

// Frames and metrics of an earlier merge into `out` would be mixed with this one's: removed.
void clear_earlier_output(const std::filesystem::path& out, const std::vector<std::string>& names) {
    if (!std::filesystem::is_directory(out)) return;
    for (const auto& entry : std::filesystem::directory_iterator(out)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("frame_", 0) == 0 || std::find(names.begin(), names.end(), name) != names.end())
            std::filesystem::remove_all(entry.path());
    }
}

// Shards sorted by first frame must follow each other: `first` is where `what` starts, `next`
// where the shards before it ended.
void require_follows(std::uint64_t first, std::uint64_t next, const std::string& what) {
    if (first == next) return;
    throw std::invalid_argument(first < next ? what + " overlaps the frames before it"
                                             : "frames " + std::to_string(next) + " to " + std::to_string(first - 1) +
                                                   " are in no shard (next: " + what + ")");
}

std::filesystem::path frame_file(const std::filesystem::path& dir, std::uint64_t frame, const std::string& format) {
    char name[48];
    std::snprintf(name, sizeof(name), "frame_%04llu.%s", static_cast<unsigned long long>(frame), format.c_str());
    return dir / name;
}

}  // namespace

merge_result merge_play_shards(const std::vector<std::filesystem::path>& dirs, const std::filesystem::path& out) {
    if (dirs.empty()) throw std::invalid_argument("merge: no shard folders given");
    std::vector<play_shard> shards;
    for (const auto& dir : dirs) shards.push_back({dir, read_metrics_json(dir / "metrics.json")});
    std::stable_sort(shards.begin(), shards.end(), [](const play_shard& a, const play_shard& b) {
        return a.metrics.info.frame_range[0] < b.metrics.info.frame_range[0];
    });
    std::uint64_t next = 0;
    for (const play_shard& shard : shards) {
        require_same(shards.front(), shard);
        const run_info& info = shard.metrics.info;
        const std::string where = shard.dir.string() + " (frames " + range_text(info.frame_range) + ")";
        if (info.partial)
            throw std::invalid_argument("shard " + where + " was interrupted (" + info.interrupted_by +
                                        ") after " + std::to_string(shard.metrics.frames.size()) +
                                        " frames: play it again");
        require_follows(info.frame_range[0], next, "shard " + where);
        if (shard.metrics.frames.size() != info.frame_range[1] - info.frame_range[0])
            throw std::invalid_argument("shard " + where + " holds " + std::to_string(shard.metrics.frames.size()) +
                                        " frame records");
        for (std::size_t i = 0; i < shard.metrics.frames.size(); ++i)
            if (shard.metrics.frames[i].frame != info.frame_range[0] + i)
                throw std::invalid_argument("shard " + where + ": record " + std::to_string(i) + " is of frame " +
                                            std::to_string(shard.metrics.frames[i].frame));
        next = info.frame_range[1];
    }
    const run_info& first = shards.front().metrics.info;
    if (next != first.path_frames)
        throw std::invalid_argument("frames " + std::to_string(next) + " to " + std::to_string(first.path_frames - 1) +
                                    " of the path are in no shard");

    // Every frame is checked before anything is written.
    const std::string format = frame_format(first.options);
    for (const play_shard& shard : shards)
        for (const frame_record& f : shard.metrics.frames)
            if (!std::filesystem::exists(frame_file(shard.dir, f.frame, format)))
                throw std::invalid_argument("shard " + shard.dir.string() + " has no image of frame " +
                                            std::to_string(f.frame) + " (" +
                                            frame_file(shard.dir, f.frame, format).filename().string() + ")");
    std::filesystem::create_directories(out);
    for (const play_shard& shard : shards)
        if (std::filesystem::equivalent(shard.dir, out))
            throw std::invalid_argument("--out " + out.string() + " is the shard folder " + shard.dir.string() +
                                        ": merge into a folder of its own (the shard's metrics.json would be lost)");
    clear_earlier_output(out, {"metrics.json"});
    merge_result result;
    run_info merged = first;
    std::vector<frame_record> frames;
    std::vector<double> setup_ms;
    merged.peak_memory_mb = 0.0;
    merged.replay_ms = 0.0;
    merged.replay_cpu_frames = merged.replay_rendered_frames = 0;
    for (const play_shard& shard : shards) {
        const run_info& info = shard.metrics.info;
        for (const frame_record& f : shard.metrics.frames) {
            const std::filesystem::path from = frame_file(shard.dir, f.frame, format);
            link_or_copy(from, out / from.filename());
            frames.push_back(f);
        }
        setup_ms.push_back(info.setup_ms);
        merged.peak_memory_mb = std::max(merged.peak_memory_mb, info.peak_memory_mb);
        merged.replay_ms += info.replay_ms;
        merged.replay_cpu_frames += info.replay_cpu_frames;
        merged.replay_rendered_frames += info.replay_rendered_frames;
        if (std::find(result.hosts.begin(), result.hosts.end(), info.host) == result.hosts.end())
            result.hosts.push_back(info.host);
        merged.shards.push_back(info);
    }
    // The summary's figures are the whole run's, recomputed from every frame (write_metrics_json);
    // setup is each shard's own, so its median stands for one.
    merged.setup_ms = median(setup_ms);
    merged.frame_range = {0, first.path_frames};
    merged.frames_planned = first.path_frames;
    // Shards may run with other thread counts (their frames are the same): 0 says several.
    for (const play_shard& shard : shards)
        if (shard.metrics.info.threads != first.threads) merged.threads = 0;
    for (const play_shard& shard : shards)
        if (shard.metrics.info.machine != first.machine) merged.machine = "several (summary.shards)";
    if (result.hosts.size() > 1) {
        merged.host.clear();
        for (const std::string& h : result.hosts) merged.host += (merged.host.empty() ? "" : ", ") + h;
        merged.host = "several: " + merged.host + " (frame times are of different machines)";
    }
    write_metrics_json(out / "metrics.json", merged, frames);
    result.shards = shards.size();
    result.frames = frames.size();
    return result;
}

namespace {

struct bench_shard_file {
    std::filesystem::path dir;
    bench_report report;
};

void require_same_bench(const bench_shard_file& a, const bench_shard_file& b) {
    const bench_report& x = a.report;
    const bench_report& y = b.report;
    const auto check = [&](bool same, const std::string& what, const std::string& xs, const std::string& ys) {
        if (!same)
            throw std::invalid_argument("bench shards " + a.dir.string() + " and " + b.dir.string() +
                                        " are not of one bench: " + what + " " + xs + " against " + ys);
    };
    check(x.scenario == y.scenario && x.source == y.source, "scenario", x.source, y.source);
    check(x.width == y.width && x.height == y.height, "size", std::to_string(x.width) + "x" + std::to_string(x.height),
          std::to_string(y.width) + "x" + std::to_string(y.height));
    check(x.gl_renderer == y.gl_renderer, "renderer", x.gl_renderer, y.gl_renderer);
    check(x.path_frames == y.path_frames, "camera path frames", std::to_string(x.path_frames),
          std::to_string(y.path_frames));
    check(x.timing_rounds == y.timing_rounds, "timing rounds", std::to_string(x.timing_rounds),
          std::to_string(y.timing_rounds));
    check(x.reference_samples_per_pixel == y.reference_samples_per_pixel, "reference samples",
          std::to_string(x.reference_samples_per_pixel), std::to_string(y.reference_samples_per_pixel));
    const auto names = [](const bench_report& r) {
        std::string out;
        for (const auto& c : r.configurations) out += (out.empty() ? "" : ",") + c.name;
        return out;
    };
    check(names(x) == names(y), "configurations (--only)", names(x), names(y));
    check(x.options == y.options, "options", run_options_text(x.options), run_options_text(y.options));
    for (std::size_t i = 0; i < x.configurations.size(); ++i) {
        const bench_configuration& cx = x.configurations[i];
        const bench_configuration& cy = y.configurations[i];
        check(cx.lighting == cy.lighting && cx.family == cy.family && cx.quality == cy.quality,
              "configuration " + cx.name, cx.family + "/" + cx.lighting, cy.family + "/" + cy.lighting);
        check(cx.selection_inputs_hash == cy.selection_inputs_hash,
              "device costs and rung tables of " + cx.name +
                  " (measured on different kinds of node? give every node the bake job's cache): hash",
              std::to_string(cx.selection_inputs_hash), std::to_string(cy.selection_inputs_hash));
    }
    const auto families = [](const bench_report& r) {
        std::string out;
        for (const auto& f : r.lighting_families) out += (out.empty() ? "" : ",") + f.name;
        return out;
    };
    check(families(x) == families(y), "lighting families", families(x), families(y));
}

// Where a shard's frames were timed: its host and thread count. Times of one domain may be
// compared; of two, never.
std::string timing_domain(const bench_shard& shard) {
    return shard.host + " (" + std::to_string(shard.threads) + " threads)";
}

// `c`'s frames timed in `domain` alone, summed up (for a time ratio within one machine).
bench_configuration frames_of_domain(const bench_configuration& c, const std::vector<bench_shard_file>& shards,
                                     const std::string& domain) {
    bench_configuration out = c;
    std::erase_if(out.frame_records, [&](const bench_frame& f) {
        for (const bench_shard_file& shard : shards)
            if (f.frame >= shard.report.range.first && f.frame < shard.report.range.end)
                return timing_domain(shard.report.range) != domain;
        return true;
    });
    summarize_records(out);
    return out;
}

}  // namespace

merge_result merge_bench_shards(const std::vector<std::filesystem::path>& dirs, const std::filesystem::path& out) {
    if (dirs.empty()) throw std::invalid_argument("merge: no shard folders given");
    std::vector<bench_shard_file> shards;
    for (const auto& dir : dirs) shards.push_back({dir, read_bench_json(dir / "bench.json")});
    std::stable_sort(shards.begin(), shards.end(), [](const bench_shard_file& a, const bench_shard_file& b) {
        return a.report.range.first < b.report.range.first;
    });
    std::uint32_t next = 0;
    for (const bench_shard_file& shard : shards) {
        require_same_bench(shards.front(), shard);
        const bench_report& r = shard.report;
        const std::string where = shard.dir.string() + " (frames " + std::to_string(r.range.first) + ":" +
                                  std::to_string(r.range.end) + ")";
        if (r.partial) throw std::invalid_argument("bench shard " + where + " was interrupted: bench it again");
        require_follows(r.range.first, next, "bench shard " + where);
        for (const bench_configuration& c : r.configurations) {
            if (c.frame_records.size() != r.range.end - r.range.first)
                throw std::invalid_argument("bench shard " + where + ": " + c.name + " holds " +
                                            std::to_string(c.frame_records.size()) + " frame records");
            for (std::size_t i = 0; i < c.frame_records.size(); ++i)
                if (c.frame_records[i].frame != r.range.first + i)
                    throw std::invalid_argument("bench shard " + where + ": " + c.name + "'s record " +
                                                std::to_string(i) + " is of frame " +
                                                std::to_string(c.frame_records[i].frame));
        }
        next = r.range.end;
    }
    const bench_report& first = shards.front().report;
    if (next != first.path_frames)
        throw std::invalid_argument("frames " + std::to_string(next) + " to " + std::to_string(first.path_frames - 1) +
                                    " of the path are in no bench shard");

    merge_result result;
    bench_report merged = first;
    merged.frames = first.path_frames;
    merged.shards.clear();
    merged.range = {0, first.path_frames, first.range.host, first.range.machine, first.range.threads, 0.0};
    for (bench_lighting_family& f : merged.lighting_families) f.reference_frame_ms.clear();
    for (bench_configuration& c : merged.configurations) {
        c.frame_records.clear();
        c.transition_records.clear();
        c.transitions_cut_off = 0;
        c.peak_memory_mb = 0.0;
    }
    std::vector<std::string> machines;
    for (const bench_shard_file& shard : shards) {
        const bench_report& r = shard.report;
        for (std::size_t i = 0; i < r.configurations.size(); ++i) {
            const bench_configuration& from = r.configurations[i];
            bench_configuration& to = merged.configurations[i];
            to.frame_records.insert(to.frame_records.end(), from.frame_records.begin(), from.frame_records.end());
            to.transition_records.insert(to.transition_records.end(), from.transition_records.begin(),
                                         from.transition_records.end());
            to.transitions_cut_off += from.transitions_cut_off;
            to.peak_memory_mb = std::max(to.peak_memory_mb, from.peak_memory_mb);
        }
        for (std::size_t i = 0; i < r.lighting_families.size(); ++i) {
            auto& ms = merged.lighting_families[i].reference_frame_ms;
            ms.insert(ms.end(), r.lighting_families[i].reference_frame_ms.begin(),
                      r.lighting_families[i].reference_frame_ms.end());
        }
        merged.range.replay_ms += r.range.replay_ms;
        merged.shards.push_back(r.range);
        if (std::find(result.hosts.begin(), result.hosts.end(), timing_domain(r.range)) == result.hosts.end())
            result.hosts.push_back(timing_domain(r.range));
        if (std::find(machines.begin(), machines.end(), r.range.machine) == machines.end())
            machines.push_back(r.range.machine);
    }
    for (bench_lighting_family& f : merged.lighting_families) f.reference_frame_ms_median = median(f.reference_frame_ms);
    for (bench_configuration& c : merged.configurations) {
        c.frame_ms_vs_baseline = std::numeric_limits<double>::quiet_NaN();
        c.frame_ms_vs_baseline_by_host.clear();
        summarize_records(c);
    }
    if (result.hosts.size() == 1) {
        add_baseline_ratios(merged);
    } else {
        // Frame times of different machines (or thread counts) never enter one ratio: each
        // domain's ratio comes from the frames it timed, where a configuration and its baseline
        // ran side by side.
        merged.range.host.clear();
        for (const std::string& h : result.hosts) merged.range.host += (merged.range.host.empty() ? "" : ", ") + h;
        merged.range.threads = 0;
        merged.threads = 0;
        merged.machine.clear();
        for (const std::string& m : machines) merged.machine += (merged.machine.empty() ? "" : "; ") + m;
        merged.machine = "several hosts or thread counts (" + merged.range.host + "): " + merged.machine;
        for (const std::string& host : result.hosts) {
            bench_report one = merged;
            for (bench_configuration& c : one.configurations) c = frames_of_domain(c, shards, host);
            add_baseline_ratios(one);
            for (std::size_t i = 0; i < one.configurations.size(); ++i)
                if (!std::isnan(one.configurations[i].frame_ms_vs_baseline))
                    merged.configurations[i].frame_ms_vs_baseline_by_host[host] = one.configurations[i].frame_ms_vs_baseline;
        }
    }
    std::filesystem::create_directories(out);
    for (const bench_shard_file& shard : shards)
        if (std::filesystem::equivalent(shard.dir, out))
            throw std::invalid_argument("--out " + out.string() + " is the shard folder " + shard.dir.string() +
                                        ": merge into a folder of its own (the shard's bench.json would be lost)");
    clear_earlier_output(out, {"bench.json", "bench.csv", "bench.svg", "summary.md", "frames"});
    // Frames saved by the shards (bench --save-frames), one folder per configuration.
    for (const bench_shard_file& shard : shards) {
        const std::filesystem::path saved = shard.dir / "frames";
        if (!std::filesystem::is_directory(saved)) continue;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(saved)) {
            const std::filesystem::path to = out / "frames" / std::filesystem::relative(entry.path(), saved);
            if (entry.is_directory())
                std::filesystem::create_directories(to);
            else
                link_or_copy(entry.path(), to);
        }
    }
    write_bench_json(out / "bench.json", merged);
    write_bench_csv(out / "bench.csv", merged);
    write_bench_plot_svg(out / "bench.svg", merged);
    write_bench_summary_md(out / "summary.md", merged);
    result.shards = shards.size();
    result.frames = merged.frames;
    return result;
}

}  // namespace sylva
