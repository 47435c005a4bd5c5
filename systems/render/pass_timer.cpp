#include "systems/render/pass_timer.h"

#include <stdexcept>

namespace sylva::render {

pass_timer::pass_timer() {
    for (auto& q : m_queries) q = make_query(GL_TIMESTAMP);
}

void pass_timer::begin(gpu_pass pass) {
    if (m_open >= 0) throw std::logic_error("pass_timer: passes cannot nest");
    m_open = static_cast<int>(pass);
    glQueryCounter(m_queries[std::size_t(2 * m_open)].id(), GL_TIMESTAMP);
}

void pass_timer::end() {
    glQueryCounter(m_queries[std::size_t(2 * m_open + 1)].id(), GL_TIMESTAMP);
    m_used[std::size_t(m_open)] = true;
    m_open = -1;
}

std::array<double, static_cast<int>(gpu_pass::count)> pass_timer::read() {
    std::array<double, k_passes> ms{};
    for (int p = 0; p < k_passes; ++p) {
        if (!m_used[std::size_t(p)]) continue;
        GLuint64 begin = 0, end = 0;
        glGetQueryObjectui64v(m_queries[std::size_t(2 * p)].id(), GL_QUERY_RESULT, &begin);
        glGetQueryObjectui64v(m_queries[std::size_t(2 * p + 1)].id(), GL_QUERY_RESULT, &end);
        ms[std::size_t(p)] = end > begin ? double(end - begin) * 1e-6 : 0.0;
        m_used[std::size_t(p)] = false;
    }
    return ms;
}

}  // namespace sylva::render
