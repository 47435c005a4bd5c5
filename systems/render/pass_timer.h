#pragma once
// GPU time per render pass from GL_TIMESTAMP queries (glQueryCounter, GL 3.3) taken before and
// after each pass, and the work each pass made the device do from ARB_pipeline_statistics_query
// (core in GL 4.6; llvmpipe has it): vertex and fragment shader invocations and the primitives
// that reached clipping. Counts, unlike times, are the same on every run, so the auto ladder's
// cost tables are measured in them (app/rung_tables.h). Results are read after the frame has
// finished on the GPU, so reading never stalls mid-frame. (GL_TIME_ELAPSED gave a nonsense
// first value on llvmpipe.)
#include <array>
#include <cstdint>
#include <string_view>

#include "systems/render/gl_objects.h"

namespace sylva::render {

// `splats`: soft point splats (visibility and blend), drawn after the sky they composite over.
// `edges`: the line style's edge pass (render.style "lines"; 0 ms in every other style).
enum class gpu_pass : int { shadow = 0, opaque, sky, shells, splats, edges, count };
constexpr std::array<std::string_view, static_cast<int>(gpu_pass::count)> k_gpu_pass_names = {
    "shadow", "opaque", "sky", "shells", "splats", "edges"};

// What one pass made the device do; all 0 where the device cannot count (has_counts()).
struct pass_work {
    std::uint64_t vertices = 0;    // vertex shader invocations
    std::uint64_t primitives = 0;  // primitives entering clipping (after culling by the API)
    std::uint64_t fragments = 0;   // fragment shader invocations (discarded ones too)
};

class pass_timer {
public:
    pass_timer();
    void begin(gpu_pass pass);
    void end();
    // Milliseconds per pass of the last frame; call after glFinish. Passes not run read 0.
    std::array<double, static_cast<int>(gpu_pass::count)> read();
    // The work per pass of the last frame; call after glFinish and before read(), which
    // forgets which passes ran.
    std::array<pass_work, static_cast<int>(gpu_pass::count)> read_work() const;
    bool has_counts() const { return m_counts; }

private:
    static constexpr int k_passes = static_cast<int>(gpu_pass::count);
    static constexpr int k_counters = 3;            // vertices, primitives, fragments
    std::array<gl_query, 2 * k_passes> m_queries;  // begin and end stamp per pass
    std::array<gl_query, k_counters * k_passes> m_work;
    bool m_counts = false;
    std::array<bool, k_passes> m_used{};
    int m_open = -1;
};

}  // namespace sylva::render
