#pragma once
// GPU time per render pass with GL_TIME_ELAPSED queries (GL 3.3 / ARB_timer_query). Results
// are read after the frame has finished on the GPU, so reading never stalls mid-frame.
#include <array>
#include <string_view>

#include "systems/render/gl_objects.h"

namespace sylva::render {

enum class gpu_pass : int { shadow = 0, opaque, sky, count };
constexpr std::array<std::string_view, static_cast<int>(gpu_pass::count)> k_gpu_pass_names = {
    "shadow", "opaque", "sky"};

class pass_timer {
public:
    pass_timer();
    void begin(gpu_pass pass);
    void end();
    // Milliseconds per pass of the last frame; call after glFinish.
    std::array<double, static_cast<int>(gpu_pass::count)> read();

private:
    std::array<gl_query, static_cast<int>(gpu_pass::count)> m_queries;
    std::array<bool, static_cast<int>(gpu_pass::count)> m_used{};
};

}  // namespace sylva::render
