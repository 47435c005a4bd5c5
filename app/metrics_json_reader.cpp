// Reads metrics.json back (read_metrics_json, app/metrics.h): `sylva merge` joins play shards
// from their frame records.
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "app/metrics.h"

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
    info.options = get("options").get<std::vector<std::string>>();
    info.selection_inputs_hash = get("selection_inputs_hash").get<std::uint64_t>();
    info.frame_range = get("frame_range").get<std::array<std::uint64_t, 2>>();
    info.path_frames = get("path_frames").get<std::uint64_t>();
    info.replay_ms = get("replay_ms").get<double>();
    info.replay_cpu_frames = get("replay_cpu_frames").get<std::uint64_t>();
    info.replay_rendered_frames = get("replay_rendered_frames").get<std::uint64_t>();
    return info;
}

}  // namespace

nlohmann::json read_json_document(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path.string() + ": cannot be read");
    try {
        return nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(path.string() + ": not JSON (" + e.what() + ")");
    }
}

metrics_file read_metrics_json(const std::filesystem::path& path) {
    const nlohmann::json root = read_json_document(path);
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
