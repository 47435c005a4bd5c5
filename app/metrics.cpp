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
        "eco_tile", "lodf", "shell", "facing_billboard"};
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
            {"options", info.options},
            {"selection_inputs_hash", info.selection_inputs_hash},
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

