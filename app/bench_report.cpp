#include "app/bench_report.h"

// bench.json, bench.csv and summary.md of `sylva bench` (the plot: app/bench_plot.cpp). Numbers
// are formatted with <charconv> (app/bench_format.h), so no output depends on the locale, and
// the same report always gives the same bytes.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <tuple>

#include "app/bench_catalogue.h"
#include "io/atomic_file.h"
#include "app/bench_format.h"
#include "app/bench_verdict.h"

namespace sylva {

namespace {

using ordered_json = nlohmann::ordered_json;
using namespace bench_format;

// --- bench.json --------------------------------------------------------------------------------

// JSON has no infinity: +-inf become the strings "inf" and "-inf", NaN becomes null.
ordered_json number(double v) {
    if (std::isnan(v)) return nullptr;
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return rounded(v);
}

ordered_json numbers(const std::map<std::string, double>& values) {
    ordered_json j = ordered_json::object();
    for (const auto& [key, v] : values) j[key] = number(v);
    return j;
}

ordered_json rounded_list(const std::vector<double>& values) {
    ordered_json j = ordered_json::array();
    for (const double v : values) j.push_back(number(v));
    return j;
}

ordered_json transitions_json(const bench_error& e) {
    ordered_json by_kind = ordered_json::object();
    for (const auto& [kind, n] : e.transitions_by_kind) by_kind[kind] = n;
    return {{"measured", e.transitions},
            {"by_kind", by_kind},
            {"mean_frames", e.transitions ? number(double(e.transition_frames) / double(e.transitions))
                                          : ordered_json(nullptr)},
            {"too_few_pixels", e.transitions_too_small},
            {"cut_off_by_path", e.transitions_cut_off}};
}

// Records keep every digit (nlohmann writes the shortest text that reads back as the same
// double): a merge recomputes the figures from them bit for bit. NaN is null.
ordered_json exact(double v) { return std::isnan(v) ? ordered_json(nullptr) : ordered_json(v); }

ordered_json exact_map(const std::map<std::string, double>& values) {
    ordered_json j = ordered_json::object();
    for (const auto& [key, v] : values) j[key] = exact(v);
    return j;
}

ordered_json records_json(const bench_configuration& c) {
    ordered_json frames = ordered_json::array();
    for (const bench_frame& f : c.frame_records) {
        ordered_json ms = ordered_json::array();
        for (const double v : f.frame_ms) ms.push_back(exact(v));
        frames.push_back({{"frame", f.frame},
                          {"frame_ms", ms},
                          {"rmse", exact(f.rmse)},
                          {"ssim", exact(f.ssim)},
                          {"perceptual", exact(f.perceptual)},
                          {"coverage_iou", exact(f.coverage_iou)},
                          {"popping", exact(f.popping)},
                          {"upload_bytes", exact(f.upload_bytes)},
                          {"cpu_ms", exact_map(f.cpu_ms)},
                          {"gpu_ms", exact_map(f.gpu_ms)},
                          {"primitives", exact_map(f.primitives)}});
    }
    ordered_json transitions = ordered_json::array();
    for (const bench_transition& t : c.transition_records)
        transitions.push_back({{"first_plant", t.first_plant},
                               {"plant_count", t.plant_count},
                               {"from_frame", t.from_frame},
                               {"to_frame", t.to_frame},
                               {"kind", t.kind},
                               {"jump", exact(t.jump)}});
    return {{"frames", frames}, {"transitions", transitions}, {"transitions_cut_off", c.transitions_cut_off}};
}

ordered_json shard_json(const bench_shard& shard) {
    return {{"frame_range", {shard.first, shard.end}},
            {"host", shard.host},
            {"machine", shard.machine},
            {"threads", shard.threads},
            {"replay_ms", exact(shard.replay_ms)}};
}

ordered_json configuration_json(const bench_configuration& c, bool on_front) {
    const bench_error& e = c.error;
    return {{"name", c.name},
            {"family", c.family},
            {"lighting", c.lighting},
            {"description", c.description},
            {"quality", number(c.quality)},
            {"frames", c.frames},
            {"frame_ms",
             {{"median", number(c.frame_ms_median)},
              {"min", number(c.frame_ms_min)},
              {"max", number(c.frame_ms_max)},
              {"round_medians", rounded_list(c.frame_ms_rounds)},
              {"vs_baseline", number(c.frame_ms_vs_baseline)},
              {"vs_baseline_by_host", numbers(c.frame_ms_vs_baseline_by_host)}}},
            {"cpu_ms", numbers(c.cpu_ms)},
            {"gpu_ms", numbers(c.gpu_ms)},
            {"primitives", numbers(c.primitives)},
            {"upload_bytes", number(c.upload_bytes)},
            {"peak_memory_mb", number(c.peak_memory_mb)},
            {"primitive_costs", numbers(c.primitive_costs)},
            {"error",
             {{"psnr", number(e.psnr_db)},
              {"ssim", number(e.ssim)},
              {"perceptual", number(e.perceptual)},
              {"coverage_iou", number(e.coverage_iou)},
              {"popping", number(e.popping)},
              {"lighting_jump", number(e.lighting_jump)},
              {"rmse", number(e.rmse)},
              {"transitions", transitions_json(e)}}},
            {"on_pareto_front", on_front},
            {"selection_inputs_hash", c.selection_inputs_hash},
            {"records", records_json(c)}};
}

ordered_json verdicts_json(const bench_report& report) {
    ordered_json out = ordered_json::array();
    for (const family_verdict& v : baseline_verdicts(report)) {
        ordered_json points = ordered_json::array();
        for (const baseline_point_verdict& p : v.points)
            points.push_back({{"baseline", p.baseline},
                              {"beaten_by", p.beaten_by.empty() ? ordered_json(nullptr) : ordered_json(p.beaten_by)},
                              {"time_ratio", p.beaten_by.empty() ? ordered_json(nullptr) : number(p.time_ratio)},
                              {"why_not", p.why_not}});
        out.push_back({{"lighting", v.lighting},
                       {"family", v.family},
                       {"configurations", v.configurations},
                       {"beats_every_baseline_point", v.beats_every_point()},
                       {"points", points}});
    }
    return out;
}

// --- bench.csv ---------------------------------------------------------------------------------

std::string csv_field(std::string_view text) {
    if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
    std::string quoted = "\"";
    for (const char ch : text) {
        if (ch == '"') quoted += '"';
        quoted += ch;
    }
    return quoted + '"';
}

// "n/a" when not measured (NaN or absent), "inf" for an infinite PSNR.
std::string csv_number(double v) {
    return std::isnan(v) ? std::string("n/a") : plain(rounded(v));
}

// --- summary.md --------------------------------------------------------------------------------

std::string ms_text(double ms) {
    return fixed(ms, ms < 10.0 ? 2 : ms < 100.0 ? 1 : 0);
}

std::string ratio_text(double ratio) {
    return fixed(ratio, ratio < 10.0 ? 2 : ratio < 100.0 ? 1 : 0) + "×";
}

std::string measured_text(double v, int decimals) {
    if (std::isnan(v)) return "n/a";
    if (std::isinf(v)) return v > 0 ? "∞" : "−∞";
    return fixed(v, decimals);
}

// Whole number with thousands separators: 2000000 -> "2,000,000".
std::string grouped(double v) {
    if (!std::isfinite(v)) return "n/a";
    const std::string digits = fixed(std::fabs(v), 0);
    std::string out = v < 0 ? "-" : "";
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string md_cell(std::string_view text) {
    std::string out;
    for (const char ch : text) {
        if (ch == '|') out += '\\';
        out += ch;
    }
    return out;
}

// The rows of one lighting family, fastest first.
std::string table_md(const bench_report& report, const std::string& lighting, const std::vector<bool>& on_front) {
    const bench_configuration* brute = family_brute_force(report, lighting);
    std::vector<std::size_t> order = in_lighting_family(report, lighting);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return report.configurations[a].frame_ms_median < report.configurations[b].frame_ms_median;
    });
    std::string md = "| configuration | median ms [min–max] | speed-up vs " + md_cell(brute ? brute->name : "brute force") +
                     " | PSNR dB | SSIM | FLIP | coverage IoU | popping | lighting jump | transitions | "
                     "triangles/frame | points/frame | lines/frame | Pareto (FLIP) |\n"
                     "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|\n";
    for (const std::size_t i : order) {
        const bench_configuration& c = report.configurations[i];
        const bench_error& e = c.error;
        const bool has_speed_up = brute && brute->frame_ms_median > 0 && c.frame_ms_median > 0;
        md += "| " + md_cell(c.name) + " | " + ms_text(c.frame_ms_median) + " [" + ms_text(c.frame_ms_min) + "–" +
              ms_text(c.frame_ms_max) + "] | " +
              (has_speed_up ? ratio_text(brute->frame_ms_median / c.frame_ms_median) : "n/a") + " | " +
              measured_text(e.psnr_db, 1) + " | " + measured_text(e.ssim, 4) + " | " +
              measured_text(e.perceptual, 4) + " | " + measured_text(e.coverage_iou, 4) + " | " +
              measured_text(e.popping, 2) + " | " + measured_text(e.lighting_jump, 2) + " | " +
              std::to_string(e.transitions) + " | " + grouped(entry_or_nan(c.primitives, "triangles")) + " | " +
              grouped(entry_or_nan(c.primitives, "points")) + " | " + grouped(entry_or_nan(c.primitives, "lines")) +
              " | " + (on_front[i] ? "★" : "") + " |\n";
    }
    return md;
}

bool is_candidate(const bench_configuration& c) { return c.family != k_family_reference; }

std::string brute_force_sentence(const bench_report& report, const std::string& lighting,
                                 const std::vector<bool>& on_front) {
    const bench_configuration* brute = family_brute_force(report, lighting);
    if (!brute) return "";
    const bench_configuration* fastest = nullptr;  // with FLIP no worse than brute force's
    const bench_configuration* closest = nullptr;  // lowest FLIP otherwise
    for (const std::size_t i : in_lighting_family(report, lighting)) {
        const bench_configuration& c = report.configurations[i];
        if (!on_front[i] || !is_candidate(c) || &c == brute) continue;
        if (c.error.perceptual <= brute->error.perceptual &&
            (!fastest || c.frame_ms_median < fastest->frame_ms_median))
            fastest = &c;
        if (!closest || c.error.perceptual < closest->error.perceptual) closest = &c;
    }
    if (!fastest) {
        std::string sentence = "No configuration on the FLIP Pareto front has error no worse than " + brute->name +
                               "'s (FLIP " + measured_text(brute->error.perceptual, 4) + " at " +
                               ms_text(brute->frame_ms_median) + " ms)";
        if (closest && closest->frame_ms_median > 0)
            sentence += "; the closest is " + closest->name + " at FLIP " +
                        measured_text(closest->error.perceptual, 4) + ", " +
                        ratio_text(time_ratio(*brute, *closest)) + " faster";
        return sentence + ".";
    }
    return "The fastest configuration on the FLIP Pareto front with error no worse than " + brute->name +
           "'s is " + fastest->name + ": FLIP " + measured_text(fastest->error.perceptual, 4) + " against " +
           measured_text(brute->error.perceptual, 4) + ", at " + ms_text(fastest->frame_ms_median) +
           " ms against " + ms_text(brute->frame_ms_median) + " ms (" +
           ratio_text(time_ratio(*brute, *fastest)) + " faster).";
}

// With several timing rounds, for an empty `lighting`: how frame times were taken; else each
// configuration's time against its family's baseline, as the median of the round-by-round
// ratios (bench_runner.h: timing_rounds).
std::string rounds_sentence(const bench_report& report, const std::string& lighting) {
    if (report.timing_rounds < 2) return "";
    if (lighting.empty())
        return "Frame times are medians over " + std::to_string(report.timing_rounds) +
               " timing rounds of every frame, the configurations alternating round by round; time ratios are "
               "medians of the round-by-round ratios.";
    const bench_configuration* baseline = family_baseline(report, lighting);
    if (!baseline) return "";
    std::string out = "Time against " + baseline->name + ":";
    bool first = true;
    for (const std::size_t i : in_lighting_family(report, lighting)) {
        const bench_configuration& c = report.configurations[i];
        if (&c == baseline || !std::isfinite(c.frame_ms_vs_baseline)) continue;
        out += std::string(first ? " " : ", ") + md_cell(c.name) + " " + ratio_text(c.frame_ms_vs_baseline);
        first = false;
    }
    return out + ".";
}

// "Similar" frame time: within 10% of the family's baseline, or faster.
std::string baseline_sentence(const bench_report& report, const std::string& lighting) {
    const bench_configuration* baseline = family_baseline(report, lighting);
    if (!baseline) return "";
    const bench_configuration* best = nullptr;
    for (const std::size_t i : in_lighting_family(report, lighting)) {
        const bench_configuration& c = report.configurations[i];
        if (&c == baseline || !is_candidate(c) || !(time_ratio(c, *baseline) <= 1.1) ||
            std::isnan(c.error.perceptual))
            continue;
        if (!best || c.error.perceptual < best->error.perceptual) best = &c;
    }
    const std::string at = baseline->name + " (FLIP " + measured_text(baseline->error.perceptual, 4) + " at " +
                           ms_text(baseline->frame_ms_median) + " ms)";
    if (!best) return "No other configuration runs within 10% of the frame time of " + at + " or faster.";
    if (!(best->error.perceptual < baseline->error.perceptual))
        return "No configuration within 10% of the frame time of " + at + " or faster has a lower FLIP error.";
    const std::string lower = best->error.perceptual > 0
                                  ? ratio_text(baseline->error.perceptual / best->error.perceptual) + " lower"
                                  : "zero";
    return "At similar or lower frame time, " + best->name + " reaches FLIP " +
           measured_text(best->error.perceptual, 4) + " at " + ms_text(best->frame_ms_median) + " ms against " +
           at + ": " + lower + " error, PSNR " + measured_text(best->error.psnr_db, 1) + " against " +
           measured_text(baseline->error.psnr_db, 1) + " dB, popping " + measured_text(best->error.popping, 2) +
           " against " + measured_text(baseline->error.popping, 2) + ".";
}

// Issue 18 item 9: per representation family, whether its sweep beats every baseline point.
std::string verdict_md(const bench_report& report, const std::string& lighting) {
    std::vector<family_verdict> verdicts;
    for (family_verdict& v : baseline_verdicts(report))
        if (v.lighting == lighting) verdicts.push_back(std::move(v));
    if (verdicts.empty()) return "";
    std::string md = "Does each representation's sweep beat the engine baseline's? A baseline point is beaten "
                     "by a configuration of the sweep at least as fast (time ratio ≤ 1";
    md += report.timing_rounds > 1 ? ", median of the round-by-round ratios" : ", one timing round";
    md += ") with SSIM at least and FLIP at most the baseline point's.\n\n| sweep |";
    for (const baseline_point_verdict& p : verdicts.front().points) md += " " + md_cell(p.baseline) + " |";
    md += " verdict |\n|---|";
    for (std::size_t i = 0; i < verdicts.front().points.size(); ++i) md += "---|";
    md += "---|\n";
    for (const family_verdict& v : verdicts) {
        md += "| " + md_cell(v.family) + " (" + std::to_string(v.configurations.size()) + ") |";
        for (const baseline_point_verdict& p : v.points)
            md += p.beaten_by.empty() ? " ✗ " + md_cell(p.why_not) + " |"
                                      : " ✓ " + md_cell(p.beaten_by) + " (" + fixed(p.time_ratio, 2) + "×) |";
        md += " " + md_cell(v.summary()) + " |\n";
    }
    return md;
}

std::string reference_sentence(const bench_report& report) {
    const bench_configuration* reference = find_configuration(report, "reference");
    if (!reference) return "";
    const bench_error& e = reference->error;
    const bool identical = std::isinf(e.psnr_db) && e.psnr_db > 0 && e.ssim == 1.0 &&
                           e.perceptual == 0.0 && e.coverage_iou == 1.0;
    return std::string("The reference measured against itself gives PSNR ") +
           measured_text(e.psnr_db, 1) + " dB, SSIM " + measured_text(e.ssim, 4) + ", FLIP " +
           measured_text(e.perceptual, 4) + ", coverage IoU " + measured_text(e.coverage_iou, 4) +
           (identical ? ": identical images, as it must."
                      : ": NOT identical, so the error measurement is suspect.");
}

}  // namespace

std::vector<std::size_t> pareto_front(const std::vector<double>& frame_ms,
                                      const std::vector<double>& error) {
    if (frame_ms.size() != error.size())
        throw std::invalid_argument("pareto_front: " + std::to_string(frame_ms.size()) +
                                    " frame times but " + std::to_string(error.size()) + " errors");
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < frame_ms.size(); ++i)
        if (!std::isnan(frame_ms[i]) && !std::isnan(error[i])) order.push_back(i);
    // Faster first, then lower error, then lower index. Each later point is then either on the
    // front by a strictly lower error than every point before it, or dominated (or an equal point's
    // copy).
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return std::tie(frame_ms[a], error[a], a) < std::tie(frame_ms[b], error[b], b);
    });
    std::vector<std::size_t> front;
    for (const std::size_t i : order)
        if (front.empty() || error[i] < error[front.back()]) front.push_back(i);
    return front;
}

void write_bench_json(const std::filesystem::path& path, const bench_report& report) {
    const std::vector<bool> on_front = front_flags(report, flip_error);
    ordered_json configurations = ordered_json::array();
    for (std::size_t i = 0; i < report.configurations.size(); ++i)
        configurations.push_back(configuration_json(report.configurations[i], on_front[i]));
    ordered_json families = ordered_json::array();
    for (const bench_lighting_family& f : report.lighting_families)
        families.push_back({{"name", f.name},
                            {"reference_lit", f.description},
                            {"reference_frame_ms_median", number(f.reference_frame_ms_median)},
                            {"reference_frame_ms", [&] {
                                 ordered_json ms = ordered_json::array();
                                 for (const double v : f.reference_frame_ms) ms.push_back(exact(v));
                                 return ms;
                             }()}});
    const ordered_json root = {{"scenario", report.scenario},
                               {"source", report.source},
                               {"machine", report.machine},
                               {"gl_renderer", report.gl_renderer},
                               {"threads", report.threads},
                               {"width", report.width},
                               {"height", report.height},
                               {"frames", report.frames},
                               {"timing_rounds", report.timing_rounds},
                               {"reference", {{"samples_per_pixel", report.reference_samples_per_pixel}}},
                               {"lighting_families", families},
                               {"primitive_costs", report.primitive_costs},
                               {"configurations", configurations},
                               {"verdicts", verdicts_json(report)},
                               {"partial", report.partial},
                               {"path_frames", report.path_frames},
                               {"options", report.options},
                               {"shard", shard_json(report.range)},
                               {"shards", [&] {
                                    ordered_json shards = ordered_json::array();
                                    for (const bench_shard& shard : report.shards) shards.push_back(shard_json(shard));
                                    return shards;
                                }()}};
    write_atomically(path, root.dump(2) + "\n");
}

void write_bench_csv(const std::filesystem::path& path, const bench_report& report) {
    const std::vector<bool> on_front = front_flags(report, flip_error);
    std::string csv =
        "name,family,lighting,quality,frames,frame_ms_median,frame_ms_min,frame_ms_max,frame_ms_vs_baseline,"
        "cpu_ms_total,gpu_ms_total,triangles,points,lines,upload_bytes,peak_memory_mb,psnr_db,ssim,perceptual,"
        "coverage_iou,popping,lighting_jump,transitions,on_pareto_front\n";
    for (std::size_t i = 0; i < report.configurations.size(); ++i) {
        const bench_configuration& c = report.configurations[i];
        const bench_error& e = c.error;
        const std::vector<std::string> fields = {csv_field(c.name),
                                                 csv_field(c.family),
                                                 csv_field(c.lighting),
                                                 csv_number(c.quality),
                                                 std::to_string(c.frames),
                                                 csv_number(c.frame_ms_median),
                                                 csv_number(c.frame_ms_min),
                                                 csv_number(c.frame_ms_max),
                                                 csv_number(c.frame_ms_vs_baseline),
                                                 csv_number(entry_or_nan(c.cpu_ms, "total")),
                                                 csv_number(entry_or_nan(c.gpu_ms, "total")),
                                                 csv_number(entry_or_nan(c.primitives, "triangles")),
                                                 csv_number(entry_or_nan(c.primitives, "points")),
                                                 csv_number(entry_or_nan(c.primitives, "lines")),
                                                 csv_number(c.upload_bytes),
                                                 csv_number(c.peak_memory_mb),
                                                 csv_number(e.psnr_db),
                                                 csv_number(e.ssim),
                                                 csv_number(e.perceptual),
                                                 csv_number(e.coverage_iou),
                                                 csv_number(e.popping),
                                                 csv_number(e.lighting_jump),
                                                 std::to_string(e.transitions),
                                                 on_front[i] ? "true" : "false"};
        for (std::size_t f = 0; f < fields.size(); ++f) csv += (f ? "," : "") + fields[f];
        csv += "\n";
    }
    write_atomically(path, csv);
}

void write_bench_summary_md(const std::filesystem::path& path, const bench_report& report) {
    const std::vector<bool> on_front = front_flags(report, flip_error);
    std::string md = "# sylva bench: " + report.scenario + "\n\n";
    md += std::to_string(report.frames) + " frames of `" + report.scenario + "` at " + std::to_string(report.width) +
          "×" + std::to_string(report.height) + "; " + report.machine + "; " + report.gl_renderer + "; " +
          std::to_string(report.threads) + " threads. Each configuration is measured against the " +
          std::to_string(report.reference_samples_per_pixel) +
          " spp full-geometry reference lit as it is, and compared only with the configurations of its "
          "lighting family (same reference): each family has its own table, Pareto front, brute force, "
          "baseline and verdict.\n\n";
    if (report.partial)
        md += "**Partial:** the bench was interrupted; configurations may be missing or cut short.\n\n";
    if (const std::string rounds = rounds_sentence(report, ""); !rounds.empty()) md += rounds + "\n\n";
    for (const bench_lighting_family& family : report.lighting_families) {
        md += "## Lighting: " + family.name + "\n\nReference: full geometry, " + family.description + " (" +
              ms_text(family.reference_frame_ms_median) + " ms/frame).\n\n";
        md += table_md(report, family.name, on_front) + "\n";
        md += "Errors are means over the frames against this reference; ★ marks the Pareto front of median "
              "frame time against FLIP among these configurations. The lighting jump is the mean colour change "
              "over whole transitions beyond the reference's (n/a: no transition measured).\n\n";
        for (const std::string& sentence :
             {rounds_sentence(report, family.name), brute_force_sentence(report, family.name, on_front),
              baseline_sentence(report, family.name)})
            if (!sentence.empty()) md += sentence + "\n\n";
        if (const std::string verdict = verdict_md(report, family.name); !verdict.empty())
            md += "### Verdict against the engine baseline\n\n" + verdict + "\n";
    }
    if (const std::string reference = reference_sentence(report); !reference.empty()) md += reference + "\n\n";
    bool any_description = false;
    for (const auto& c : report.configurations) any_description = any_description || !c.description.empty();
    if (any_description) {
        md += "## Configurations\n\n";
        for (const auto& c : report.configurations)
            if (!c.description.empty()) md += "- `" + c.name + "` (" + c.lighting + "): " + c.description + "\n";
    }
    write_atomically(path, md);
}

}  // namespace sylva
