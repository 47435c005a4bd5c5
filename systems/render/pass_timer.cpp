#include "systems/render/pass_timer.h"

namespace sylva::render {

pass_timer::pass_timer() {
    for (auto& q : m_queries) q = make_query(GL_TIME_ELAPSED);
}

void pass_timer::begin(gpu_pass pass) {
    const auto i = static_cast<std::size_t>(pass);
    glBeginQuery(GL_TIME_ELAPSED, m_queries[i].id());
    m_used[i] = true;
}

void pass_timer::end() { glEndQuery(GL_TIME_ELAPSED); }

std::array<double, static_cast<int>(gpu_pass::count)> pass_timer::read() {
    std::array<double, static_cast<int>(gpu_pass::count)> ms{};
    for (std::size_t i = 0; i < m_queries.size(); ++i) {
        if (!m_used[i]) continue;
        GLuint64 ns = 0;
        glGetQueryObjectui64v(m_queries[i].id(), GL_QUERY_RESULT, &ns);
        ms[i] = double(ns) * 1e-6;
        m_used[i] = false;
    }
    return ms;
}

}  // namespace sylva::render
