#include "app/metrics.h"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>
#include <unistd.h>

#include "app/process_memory.h"
#include "io/atomic_file.h"

namespace sylva {

std::string_view representation_name(representation r) {
    constexpr std::array<std::string_view, static_cast<std::size_t>(representation::count)> k_names = {
        "none", "mesh_full", "mesh_reduced", "mesh_far", "crossed_billboard", "points", "billboard_cloud",
        "eco_tile", "lodf", "shell"};
    return k_names[static_cast<std::size_t>(r)];
}

std::string describe_machine() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    std::string model = "unknown CPU";
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    }
    return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
}

std::string host_name() {
    char name[256] = {};
    if (gethostname(name, sizeof(name) - 1) != 0) return "unknown host";
    return name;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const std::size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(mid), values.end());
    double m = values[mid];
    if (values.size() % 2 == 0) {
        const double lower = *std::max_element(values.begin(), values.begin() + std::ptrdiff_t(mid));
        m = 0.5 * (m + lower);
    }
    return m;
}

namespace {

nlohmann::json named_ms(const std::vector<std::pair<std::string, double>>& entries) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [name, ms] : entries) j[name] = ms;
    return j;
}

nlohmann::json frame_json(const frame_record& f) {
    nlohmann::json instances = nlohmann::json::object();
    for (std::size_t r = 1; r < f.instances.size(); ++r)
        instances[std::string(representation_name(static_cast<representation>(r)))] = f.instances[r];
    nlohmann::json work = nullptr;  // null where the device cannot count shader invocations
    if (f.work_counted)
        work = {{"vertices", f.vertices},
                {"fragments", f.fragments},
                {"shadow_vertices", f.shadow_vertices},
                {"shadow_fragments", f.shadow_fragments}};
    return {{"frame", f.frame},
            {"time_s", f.time_s},
            {"frame_ms", f.frame_ms},
            {"cpu_ms", f.cpu_ms},
            {"gpu_ms", f.gpu_ms},
            {"systems", named_ms(f.systems)},
            {"passes", named_ms(f.passes)},
            {"triangles", f.triangles},
            {"shadow_triangles", f.shadow_triangles},
            {"shadow_texel_m", f.shadow_texel_m},
            {"shadow_split_m", f.shadow_split_m},
            {"shadow_drawn", f.shadow_drawn},
            {"points", f.points},
            {"lines", f.lines},
            {"shader_work", work},
            {"instances", instances},
            {"submit_record_ms", f.submit_record_ms},
            {"submit_issue_ms", f.submit_issue_ms},
            {"upload_bytes", f.upload_bytes},
            {"lodf_command_bytes", f.lodf_command_bytes},
            {"lodf_changed_clusters", f.lodf_changed_clusters},
            {"lodf_overflow", f.lodf_overflow},
            {"draw_calls", f.draw_calls},
            {"aggregated_tiles", f.aggregated_tiles},
            {"aggregated_plants", f.aggregated_plants},
            {"ladder_lambda", f.ladder_lambda},
            {"predicted_plant_ms", f.predicted_plant_ms},
            {"plant_budget_ms", f.plant_budget_ms},
            {"image_hash", f.image_hash},
            {"state_hash", f.state_hash}};
}

// Median of one named entry (system or pass) over all frames.
nlohmann::json median_by_name(const std::vector<frame_record>& frames,
                              std::vector<std::pair<std::string, double>> frame_record::*field) {
    nlohmann::json out = nlohmann::json::object();
    if (frames.empty()) return out;
    for (std::size_t i = 0; i < (frames.front().*field).size(); ++i) {
        std::vector<double> values;
        for (const auto& f : frames) values.push_back((f.*field)[i].second);
        out[(frames.front().*field)[i].first] = median(values);
    }
    return out;
}

nlohmann::json shard_json(const run_info& shard) {
    return {{"frame_range", shard.frame_range},
            {"host", shard.host},
            {"machine", shard.machine},
            {"threads", shard.threads},
            {"setup_ms", shard.setup_ms},
            {"replay_ms", shard.replay_ms},
            {"replay_cpu_frames", shard.replay_cpu_frames},
            {"replay_rendered_frames", shard.replay_rendered_frames},
            {"peak_memory_mb", shard.peak_memory_mb}};
}

nlohmann::json summary_json(const run_info& info, const std::vector<frame_record>& frames) {
    auto med = [&](double frame_record::*field) {
        std::vector<double> values;
        for (const auto& f : frames) values.push_back(f.*field);
        return median(values);
    };
    std::vector<double> triangles;
    for (const auto& f : frames) triangles.push_back(double(f.triangles));
    return {{"scenario", info.scenario},
            {"source", info.source},
            {"frames", frames.size()},
            {"frames_planned", std::max<std::uint64_t>(info.frames_planned, frames.size())},
            {"partial", info.partial},
            {"interrupted_by", info.interrupted_by.empty() ? nlohmann::json(nullptr)
                                                           : nlohmann::json(info.interrupted_by)},
            {"width", info.width},
            {"height", info.height},
            {"threads", info.threads},
            {"plants", info.plants},
            {"source_triangles", info.source_triangles},
            {"setup_ms", info.setup_ms},
            {"static_upload_bytes", info.static_upload_bytes},
            {"shell_bytes", info.shell_bytes},
            {"peak_memory_mb", info.peak_memory_mb >= 0.0 ? info.peak_memory_mb : peak_resident_mb()},
            {"mode", info.mode},
            {"samples_per_pixel", info.samples_per_pixel},
            {"median_frame_ms", med(&frame_record::frame_ms)},
            {"median_cpu_ms", med(&frame_record::cpu_ms)},
            {"median_gpu_ms", med(&frame_record::gpu_ms)},
            {"median_triangles", median(triangles)},
            {"median_systems_ms", median_by_name(frames, &frame_record::systems)},
            {"median_passes_ms", median_by_name(frames, &frame_record::passes)},
            {"machine", info.machine},
            {"gl_renderer", info.gl_renderer},
            {"gl_version", info.gl_version},
            {"gl_backend", info.backend},
            {"host", info.host},
            {"frame_range", info.frame_range},
            {"path_frames", info.path_frames},
            {"replay_ms", info.replay_ms},
            {"replay_cpu_frames", info.replay_cpu_frames},
            {"replay_rendered_frames", info.replay_rendered_frames},
            {"shards", [&] {
                 nlohmann::json shards = nlohmann::json::array();
                 for (const run_info& shard : info.shards) shards.push_back(shard_json(shard));
                 return shards;
             }()}};
}

}  // namespace

void write_metrics_json(const std::filesystem::path& path, const run_info& info,
                        const std::vector<frame_record>& frames) {
    nlohmann::json root;
    root["frames"] = nlohmann::json::array();
    for (const auto& f : frames) root["frames"].push_back(frame_json(f));
    root["summary"] = summary_json(info, frames);
    write_atomically(path, root.dump(2) + "\n");
}

}  // namespace sylva

namespace sylva {
namespace {

// A field of `j`, or a runtime_error naming the file and the field's JSON path.
const nlohmann::json& field(const nlohmann::json& j, const char* key, const std::filesystem::path& path,
                            const std::string& where) {
    if (!j.is_object() || !j.contains(key))
        throw std::runtime_error(path.string() + ": " + where + "." + key + " is missing (not a metrics.json of this Sylva?)");
    return j.at(key);
}

std::vector<std::pair<std::string, double>> named_ms_from(const nlohmann::json& j) {
    std::vector<std::pair<std::string, double>> out;
    for (const auto& [name, ms] : j.items()) out.emplace_back(name, ms.get<double>());
    return out;
}

frame_record frame_from_json(const nlohmann::json& j, const std::filesystem::path& path, const std::string& where) {
    const auto get = [&](const char* key) -> const nlohmann::json& { return field(j, key, path, where); };
    frame_record f;
    f.frame = get("frame").get<std::uint64_t>();
    f.time_s = get("time_s").get<double>();
    f.frame_ms = get("frame_ms").get<double>();
    f.cpu_ms = get("cpu_ms").get<double>();
    f.gpu_ms = get("gpu_ms").get<double>();
    f.systems = named_ms_from(get("systems"));
    f.passes = named_ms_from(get("passes"));
    f.triangles = get("triangles").get<std::uint64_t>();
    f.shadow_triangles = get("shadow_triangles").get<std::uint64_t>();
    f.shadow_texel_m = get("shadow_texel_m").get<std::vector<double>>();
    f.shadow_split_m = get("shadow_split_m").get<std::vector<double>>();
    f.shadow_drawn = get("shadow_drawn").get<std::vector<int>>();
    f.points = get("points").get<std::uint64_t>();
    f.lines = get("lines").get<std::uint64_t>();
    if (const nlohmann::json& work = get("shader_work"); !work.is_null()) {
        f.work_counted = true;
        f.vertices = field(work, "vertices", path, where + ".shader_work").get<std::uint64_t>();
        f.fragments = field(work, "fragments", path, where + ".shader_work").get<std::uint64_t>();
        f.shadow_vertices = field(work, "shadow_vertices", path, where + ".shader_work").get<std::uint64_t>();
        f.shadow_fragments = field(work, "shadow_fragments", path, where + ".shader_work").get<std::uint64_t>();
    }
    for (const auto& [name, count] : get("instances").items()) {
        std::size_t r = 1;
        while (r < f.instances.size() && representation_name(static_cast<representation>(r)) != name) ++r;
        if (r == f.instances.size())
            throw std::runtime_error(path.string() + ": " + where + ".instances." + name + " is no representation");
        f.instances[r] = count.get<std::uint32_t>();
    }
    f.submit_record_ms = get("submit_record_ms").get<double>();
    f.submit_issue_ms = get("submit_issue_ms").get<double>();
    f.upload_bytes = get("upload_bytes").get<std::uint64_t>();
    f.lodf_command_bytes = get("lodf_command_bytes").get<std::uint64_t>();
    f.lodf_changed_clusters = get("lodf_changed_clusters").get<std::uint32_t>();
    f.lodf_overflow = get("lodf_overflow").get<std::uint32_t>();
    f.draw_calls = get("draw_calls").get<std::uint32_t>();
    f.aggregated_tiles = get("aggregated_tiles").get<std::uint32_t>();
    f.aggregated_plants = get("aggregated_plants").get<std::uint32_t>();
    f.ladder_lambda = get("ladder_lambda").get<double>();
    f.predicted_plant_ms = get("predicted_plant_ms").get<double>();
    f.plant_budget_ms = get("plant_budget_ms").get<double>();
    f.image_hash = get("image_hash").get<std::uint64_t>();
    f.state_hash = get("state_hash").get<std::uint64_t>();
    return f;
}

run_info info_from_json(const nlohmann::json& j, const std::filesystem::path& path) {
    const auto get = [&](const char* key) -> const nlohmann::json& { return field(j, key, path, "summary"); };
    run_info info;
    info.scenario = get("scenario").get<std::string>();
    info.source = get("source").get<std::string>();
    info.frames_planned = get("frames_planned").get<std::uint64_t>();
    info.partial = get("partial").get<bool>();
    if (!get("interrupted_by").is_null()) info.interrupted_by = get("interrupted_by").get<std::string>();
    info.width = get("width").get<std::uint32_t>();
    info.height = get("height").get<std::uint32_t>();
    info.threads = get("threads").get<int>();
    info.plants = get("plants").get<std::size_t>();
    info.source_triangles = get("source_triangles").get<std::uint64_t>();
    info.setup_ms = get("setup_ms").get<double>();
    info.static_upload_bytes = get("static_upload_bytes").get<std::uint64_t>();
    info.shell_bytes = get("shell_bytes").get<std::uint64_t>();
    info.peak_memory_mb = get("peak_memory_mb").get<double>();
    info.mode = get("mode").get<std::string>();
    info.samples_per_pixel = get("samples_per_pixel").get<std::uint32_t>();
    info.machine = get("machine").get<std::string>();
    info.gl_renderer = get("gl_renderer").get<std::string>();
    info.gl_version = get("gl_version").get<std::string>();
    info.backend = get("gl_backend").get<std::string>();
    info.host = get("host").get<std::string>();
    info.frame_range = get("frame_range").get<std::array<std::uint64_t, 2>>();
    info.path_frames = get("path_frames").get<std::uint64_t>();
    info.replay_ms = get("replay_ms").get<double>();
    info.replay_cpu_frames = get("replay_cpu_frames").get<std::uint64_t>();
    info.replay_rendered_frames = get("replay_rendered_frames").get<std::uint64_t>();
    return info;
}

}  // namespace

metrics_file read_metrics_json(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path.string() + ": cannot be read");
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(path.string() + ": not JSON (" + e.what() + ")");
    }
    metrics_file out;
    try {
        out.info = info_from_json(field(root, "summary", path, "$"), path);
        const nlohmann::json& frames = field(root, "frames", path, "$");
        for (std::size_t i = 0; i < frames.size(); ++i)
            out.frames.push_back(frame_from_json(frames[i], path, "frames[" + std::to_string(i) + "]"));
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(path.string() + ": a field has the wrong type (" + e.what() + ")");
    }
    return out;
}

}  // namespace sylva
