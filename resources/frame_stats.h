#pragma once
// What the submission measured for the frame, for metrics.json. The renderer fills the GPU
// part (render::renderer::finish), the submit system (main thread) adds its CPU timings.
#include <array>
#include <cstdint>

namespace sylva {

struct frame_stats {
    // shadow, opaque, sky, shells, splats, edges (render::k_gpu_pass_names)
    std::array<double, 6> gpu_pass_ms{};
    // What each pass made the device do (render::pass_timer::read_work): vertex and fragment
    // shader invocations, primitives entering clipping; counted only where the device can.
    bool work_counted = false;
    std::array<std::uint64_t, 6> pass_vertices{};
    std::array<std::uint64_t, 6> pass_primitives{};
    std::array<std::uint64_t, 6> pass_fragments{};
    double gpu_ms = 0.0;
    double submit_cpu_ms = 0.0;  // issuing the frame's GL commands (includes driver work)
    // Sylva's own part of it: uniforms, instance records and indirect commands written to the
    // ring before the first draw call (on llvmpipe the draw calls add vertex processing).
    double record_ms = 0.0;
    double finish_ms = 0.0;  // time spent waiting for the GPU to finish
    std::uint64_t upload_bytes = 0;
    // Of those, the LoDF slots' indirect commands rewritten (Rebollo 2006 §4: changed clusters only).
    std::uint64_t lodf_command_bytes = 0;
    std::uint32_t draw_calls = 0;
    std::uint32_t indirect_commands = 0;
};

}  // namespace sylva
