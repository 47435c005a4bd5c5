// Reads bench.json back (read_bench_json, app/bench_report.h): the configurations' identities
// and their per-frame records, from which `sylva merge` recomputes a sharded bench's figures.
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "app/bench_report.h"
#include "app/metrics.h"

namespace sylva {
namespace {

struct reader {
    const std::filesystem::path& path;

    const nlohmann::json& at(const nlohmann::json& j, const char* key, const std::string& where) const {
        if (!j.is_object() || !j.contains(key))
            throw std::runtime_error(path.string() + ": " + where + "." + key +
                                     " is missing (written by a Sylva without per-frame records? bench again)");
        return j.at(key);
    }
    // A number that may be null (not measured), "inf" or "-inf".
    double number(const nlohmann::json& j) const {
        if (j.is_null()) return std::numeric_limits<double>::quiet_NaN();
        if (j.is_string()) {
            const std::string text = j.get<std::string>();
            if (text == "inf") return std::numeric_limits<double>::infinity();
            if (text == "-inf") return -std::numeric_limits<double>::infinity();
            throw std::runtime_error(path.string() + ": '" + text + "' is no number");
        }
        return j.get<double>();
    }
    std::map<std::string, double> numbers(const nlohmann::json& j) const {
        std::map<std::string, double> out;
        for (const auto& [key, v] : j.items()) out[key] = number(v);
        return out;
    }
    bench_shard shard(const nlohmann::json& j, const std::string& where) const {
        bench_shard s;
        const auto range = at(j, "frame_range", where).get<std::array<std::uint32_t, 2>>();
        s.first = range[0];
        s.end = range[1];
        s.host = at(j, "host", where).get<std::string>();
        s.machine = at(j, "machine", where).get<std::string>();
        s.threads = at(j, "threads", where).get<int>();
        s.replay_ms = number(at(j, "replay_ms", where));
        return s;
    }
    bench_configuration configuration(const nlohmann::json& j, const std::string& where) const {
        bench_configuration c;
        c.name = at(j, "name", where).get<std::string>();
        c.family = at(j, "family", where).get<std::string>();
        c.lighting = at(j, "lighting", where).get<std::string>();
        c.description = at(j, "description", where).get<std::string>();
        c.quality = number(at(j, "quality", where));
        c.peak_memory_mb = number(at(j, "peak_memory_mb", where));
        c.primitive_costs = numbers(at(j, "primitive_costs", where));
        c.selection_inputs_hash = at(j, "selection_inputs_hash", where).get<std::uint64_t>();
        // The figures themselves are recomputed from the records (summarize_records), but the
        // time ratios need the other configurations: read as written.
        const nlohmann::json& times = at(j, "frame_ms", where);
        c.frame_ms_vs_baseline = number(at(times, "vs_baseline", where + ".frame_ms"));
        c.frame_ms_vs_baseline_by_host = numbers(at(times, "vs_baseline_by_host", where + ".frame_ms"));
        const std::string in = where + ".records";
        const nlohmann::json& records = at(j, "records", where);
        const nlohmann::json& frames = at(records, "frames", in);
        for (std::size_t i = 0; i < frames.size(); ++i) {
            const nlohmann::json& f = frames[i];
            const std::string fw = in + ".frames[" + std::to_string(i) + "]";
            bench_frame r;
            r.frame = at(f, "frame", fw).get<std::uint32_t>();
            for (const auto& ms : at(f, "frame_ms", fw)) r.frame_ms.push_back(number(ms));
            r.rmse = number(at(f, "rmse", fw));
            r.ssim = number(at(f, "ssim", fw));
            r.perceptual = number(at(f, "perceptual", fw));
            r.coverage_iou = number(at(f, "coverage_iou", fw));
            r.popping = number(at(f, "popping", fw));
            r.upload_bytes = number(at(f, "upload_bytes", fw));
            r.cpu_ms = numbers(at(f, "cpu_ms", fw));
            r.gpu_ms = numbers(at(f, "gpu_ms", fw));
            r.primitives = numbers(at(f, "primitives", fw));
            c.frame_records.push_back(std::move(r));
        }
        const nlohmann::json& transitions = at(records, "transitions", in);
        for (std::size_t i = 0; i < transitions.size(); ++i) {
            const nlohmann::json& t = transitions[i];
            const std::string tw = in + ".transitions[" + std::to_string(i) + "]";
            c.transition_records.push_back({at(t, "first_plant", tw).get<std::uint32_t>(),
                                            at(t, "plant_count", tw).get<std::uint32_t>(),
                                            at(t, "from_frame", tw).get<std::uint32_t>(),
                                            at(t, "to_frame", tw).get<std::uint32_t>(),
                                            at(t, "kind", tw).get<std::string>(), number(at(t, "jump", tw))});
        }
        c.transitions_cut_off = at(records, "transitions_cut_off", in).get<std::uint64_t>();
        return c;
    }
};

}  // namespace

bench_report read_bench_json(const std::filesystem::path& path) {
    const nlohmann::json root = read_json_document(path);
    const reader r{path};
    bench_report report;
    try {
        report.scenario = r.at(root, "scenario", "$").get<std::string>();
        report.source = r.at(root, "source", "$").get<std::string>();
        report.machine = r.at(root, "machine", "$").get<std::string>();
        report.gl_renderer = r.at(root, "gl_renderer", "$").get<std::string>();
        report.threads = r.at(root, "threads", "$").get<int>();
        report.width = r.at(root, "width", "$").get<std::uint32_t>();
        report.height = r.at(root, "height", "$").get<std::uint32_t>();
        report.frames = r.at(root, "frames", "$").get<std::uint32_t>();
        report.timing_rounds = r.at(root, "timing_rounds", "$").get<std::uint32_t>();
        report.reference_samples_per_pixel =
            r.at(r.at(root, "reference", "$"), "samples_per_pixel", "$.reference").get<std::uint32_t>();
        const nlohmann::json& families = r.at(root, "lighting_families", "$");
        for (std::size_t i = 0; i < families.size(); ++i) {
            const std::string where = "$.lighting_families[" + std::to_string(i) + "]";
            bench_lighting_family f;
            f.name = r.at(families[i], "name", where).get<std::string>();
            f.description = r.at(families[i], "reference_lit", where).get<std::string>();
            f.reference_frame_ms_median = r.number(r.at(families[i], "reference_frame_ms_median", where));
            for (const auto& ms : r.at(families[i], "reference_frame_ms", where))
                f.reference_frame_ms.push_back(r.number(ms));
            report.lighting_families.push_back(std::move(f));
        }
        report.primitive_costs = r.numbers(r.at(root, "primitive_costs", "$"));
        const nlohmann::json& configurations = r.at(root, "configurations", "$");
        for (std::size_t i = 0; i < configurations.size(); ++i)
            report.configurations.push_back(
                r.configuration(configurations[i], "$.configurations[" + std::to_string(i) + "]"));
        report.partial = r.at(root, "partial", "$").get<bool>();
        report.path_frames = r.at(root, "path_frames", "$").get<std::uint32_t>();
        report.options = r.at(root, "options", "$").get<std::vector<std::string>>();
        report.range = r.shard(r.at(root, "shard", "$"), "$.shard");
        const nlohmann::json& shards = r.at(root, "shards", "$");
        for (std::size_t i = 0; i < shards.size(); ++i)
            report.shards.push_back(r.shard(shards[i], "$.shards[" + std::to_string(i) + "]"));
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(path.string() + ": a field has the wrong type (" + e.what() + ")");
    }
    return report;
}

}  // namespace sylva
