#include "systems/render/pass_timer.h"

#include <stdexcept>

namespace sylva::render {

namespace {
constexpr std::array<GLenum, 3> k_counter_targets{GL_VERTEX_SHADER_INVOCATIONS_ARB,
                                                  GL_CLIPPING_INPUT_PRIMITIVES_ARB,
                                                  GL_FRAGMENT_SHADER_INVOCATIONS_ARB};
}  // namespace

pass_timer::pass_timer() : m_counts(GLAD_GL_ARB_pipeline_statistics_query != 0) {
    for (auto& q : m_queries) q = make_query(GL_TIMESTAMP);
    // glGenQueries, not glCreateQueries: Mesa 22 refuses the pipeline statistics targets there
    // (GL_INVALID_ENUM); a generated name takes its target at its first glBeginQuery.
    if (m_counts)
        for (auto& q : m_work) {
            GLuint id = 0;
            glGenQueries(1, &id);
            q = gl_query(id);
        }
}

void pass_timer::begin(gpu_pass pass) {
    if (m_open >= 0) throw std::logic_error("pass_timer: passes cannot nest");
    m_open = static_cast<int>(pass);
    glQueryCounter(m_queries[std::size_t(2 * m_open)].id(), GL_TIMESTAMP);
    if (m_counts)
        for (int c = 0; c < k_counters; ++c)
            glBeginQuery(k_counter_targets[std::size_t(c)], m_work[std::size_t(k_counters * m_open + c)].id());
}

void pass_timer::end() {
    if (m_counts)
        for (const GLenum target : k_counter_targets) glEndQuery(target);
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

std::array<pass_work, static_cast<int>(gpu_pass::count)> pass_timer::read_work() const {
    std::array<pass_work, k_passes> work{};
    if (!m_counts) return work;
    for (int p = 0; p < k_passes; ++p) {
        if (!m_used[std::size_t(p)]) continue;
        std::array<GLuint64, k_counters> n{};
        for (int c = 0; c < k_counters; ++c)
            glGetQueryObjectui64v(m_work[std::size_t(k_counters * p + c)].id(), GL_QUERY_RESULT, &n[std::size_t(c)]);
        work[std::size_t(p)] = {n[0], n[1], n[2]};
    }
    return work;
}

}  // namespace sylva::render
