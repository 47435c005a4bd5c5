#pragma once
// GPU time per render pass from GL_TIMESTAMP queries (glQueryCounter, GL 3.3) taken before and
// after each pass. Results are read after the frame has finished on the GPU, so reading never
// stalls mid-frame. (GL_TIME_ELAPSED gave a nonsense first value on llvmpipe.)
#include <array>
#include <string_view>

#include "systems/render/gl_objects.h"

namespace sylva::render {

// `splats`: soft point splats (visibility and blend), drawn after the sky they composite over.
enum class gpu_pass : int { shadow = 0, opaque, sky, splats, count };
constexpr std::array<std::string_view, static_cast<int>(gpu_pass::count)> k_gpu_pass_names = {
    "shadow", "opaque", "sky", "splats"};

class pass_timer {
public:
    pass_timer();
    void begin(gpu_pass pass);
    void end();
    // Milliseconds per pass of the last frame; call after glFinish. Passes not run read 0.
    std::array<double, static_cast<int>(gpu_pass::count)> read();

private:
    static constexpr int k_passes = static_cast<int>(gpu_pass::count);
    std::array<gl_query, 2 * k_passes> m_queries;  // begin and end stamp per pass
    std::array<bool, k_passes> m_used{};
    int m_open = -1;
};

}  // namespace sylva::render
