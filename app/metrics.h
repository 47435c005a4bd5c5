#pragma once
// Per-frame measurements and their JSON form (metrics.json): what a frame cost on the CPU per
// system, on the GPU per pass, what it drew and uploaded, and hashes of its image and state that
// must not depend on the thread count.
#include <array>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "components/lod_state.h"

namespace sylva {

struct frame_record {
    std::uint64_t frame = 0;
    double time_s = 0.0;
    double frame_ms = 0.0;  // wall time of the whole frame, GPU finished
    double cpu_ms = 0.0;    // systems plus GL command recording, without waiting for the GPU
    double gpu_ms = 0.0;    // sum of the GPU pass timers
    std::vector<std::pair<std::string, double>> systems;  // ms per system, schedule order
    std::vector<std::pair<std::string, double>> passes;   // GPU ms per render pass
    std::uint64_t triangles = 0;         // in the camera's view
    std::uint64_t shadow_triangles = 0;  // in the shadow cascades
    // Metres per shadow-map texel in each cascade, near to far, and where each ends (view depth).
    std::vector<double> shadow_texel_m;
    std::vector<double> shadow_split_m;
    // Per cascade, whether its slice may hold a receiver and so was drawn (1) or shades only
    // air and was skipped (0; resources/shadow_receivers.h).
    std::vector<int> shadow_drawn;
    // Metres per texel of the finest cascade any plant's shadow was drawn into (0: none cast):
    // in a scene of one plant, the shadow-map density its shadow's fragments were shaded at
    // (app/rung_tables.h rung_measurement::shadow_texel_m).
    double caster_texel_m = 0.0;
    std::uint64_t points = 0;
    std::uint64_t lines = 0;
    // The shader work the frame made the device do (render::pass_timer::read_work): the view's
    // passes summed, the shadow pass apart. Only where the device counts (work_counted).
    bool work_counted = false;
    std::uint64_t vertices = 0;   // vertex shader invocations
    std::uint64_t fragments = 0;  // fragment shader invocations
    std::uint64_t shadow_vertices = 0;
    std::uint64_t shadow_fragments = 0;
    std::array<std::uint32_t, static_cast<std::size_t>(representation::count)> instances{};
    double submit_record_ms = 0.0;  // Sylva's CPU work to prepare the GL submission
    double submit_issue_ms = 0.0;   // issuing the GL calls (llvmpipe does vertex work here)
    std::uint64_t upload_bytes = 0;
    // Rebollo 2006: of those, the LoDF slots' indirect commands rewritten, and the clusters whose
    // counters changed; plants on the LoDF rung without a slot (drawn as mesh_full).
    std::uint64_t lodf_command_bytes = 0;
    std::uint32_t lodf_changed_clusters = 0;
    std::uint32_t lodf_overflow = 0;
    std::uint32_t draw_calls = 0;
    // Deussen 2002 §6.2: far eco tiles drawn as their aggregated point sets, and their plants.
    std::uint32_t aggregated_tiles = 0;
    std::uint32_t aggregated_plants = 0;
    // The auto ladder (resources/rung_budget.h): the solver's multiplier λ (error per µs) and
    // the plants' cost it predicted, in ms; both 0 without measured rung tables.
    double ladder_lambda = 0.0;
    double predicted_plant_ms = 0.0;
    double plant_budget_ms = 0.0;  // what the solver held them to (adapted under a frame-time target)
    std::uint64_t image_hash = 0;  // FNV-1a of the captured RGBA8 pixels (0 when not captured)
    std::uint64_t state_hash = 0;  // FNV-1a of the frame's component state and draw list
};

struct run_info {
    std::string scenario;
    std::string source;
    std::string gl_renderer;
    std::string gl_version;
    std::string backend;
    std::string machine;  // CPU model and core count
    int threads = 0;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::size_t plants = 0;
    std::uint64_t source_triangles = 0;
    double setup_ms = 0.0;  // building assets, world and GPU resources
    std::uint64_t static_upload_bytes = 0;  // meshes, textures and shells uploaded once at start
    std::uint64_t shell_bytes = 0;          // of which the shells' (textures, index, slice grids)
    std::string mode = "lod";  // lod, full_geometry or reference
    std::uint32_t samples_per_pixel = 1;
    // An interrupted run (app/interrupt.h) keeps the frames it finished: partial is true,
    // interrupted_by names the signal ("SIGINT"), frames_planned says how many were asked for.
    bool partial = false;
    std::string interrupted_by;
    std::uint64_t frames_planned = 0;
    // A shard (app/frame_range.h): the frames [first, end) of a camera path of path_frames
    // frames, and what reaching its first frame cost (all 0 for a run from frame 0).
    std::array<std::uint64_t, 2> frame_range{0, 0};
    std::uint64_t path_frames = 0;
    std::uint64_t replay_cpu_frames = 0;
    std::uint64_t replay_rendered_frames = 0;
    double replay_ms = 0.0;
    double peak_memory_mb = -1.0;  // resident high-water mark; negative: this process's when written
    std::string host;  // where it ran (timings of different hosts are never compared)
    // What every shard of one run must share (sylva merge checks): the command's options but
    // the shard's own (app/run_options.h), and a hash of what selection reads from the device
    // (primitive costs, the auto ladder's tables; scenario_player::selection_inputs_hash).
    std::vector<std::string> options;
    std::uint64_t selection_inputs_hash = 0;
    // Merged shards (sylva merge): one entry per shard, in frame order; empty for one run.
    std::vector<run_info> shards;
};

std::string_view representation_name(representation r);
std::string describe_machine();
double median(std::vector<double> values);

std::string host_name();

// Writes metrics.json atomically (temporary file, then rename); throws naming the path.
void write_metrics_json(const std::filesystem::path& path, const run_info& info,
                        const std::vector<frame_record>& frames);

// A JSON file's document (the readers of metrics.json and bench.json); throws
// std::runtime_error naming the path when it cannot be read or is not JSON.
nlohmann::json read_json_document(const std::filesystem::path& path);

// Reads what write_metrics_json wrote (sylva merge); throws std::runtime_error naming the
// path and the field that is missing or wrong.
struct metrics_file {
    run_info info;
    std::vector<frame_record> frames;
};
metrics_file read_metrics_json(const std::filesystem::path& path);

}  // namespace sylva
