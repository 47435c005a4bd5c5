#include "ecs/command_buffer.h"

#include <stdexcept>

namespace sylva::ecs {

entity command_buffer::create() {
    const entity placeholder{m_placeholders++, k_placeholder_generation};
    m_commands.push_back({op::create, placeholder, nullptr, 0});
    return placeholder;
}

void command_buffer::destroy(entity e) {
    m_commands.push_back({op::destroy, e, nullptr, 0});
}

void command_buffer::append(command_buffer& other) {
    const std::size_t payload_base = m_payload.size();
    for (command c : other.m_commands) {
        c.payload += payload_base;
        if (is_placeholder(c.target)) c.target.index += m_placeholders;
        m_commands.push_back(c);
    }
    m_payload.insert(m_payload.end(), other.m_payload.begin(), other.m_payload.end());
    m_placeholders += other.m_placeholders;
    other.clear();
}

entity command_buffer::resolve(entity e) const {
    if (!is_placeholder(e)) return e;
    if (e.index >= m_created.size())
        throw std::logic_error("ecs::command_buffer: placeholder entity from another buffer");
    return m_created[e.index];
}

void command_buffer::apply(world& w) {
    m_created.clear();
    for (const command& c : m_commands) {
        if (c.kind == op::create) {
            m_created.push_back(w.create());
            continue;
        }
        const entity target = resolve(c.target);
        if (c.kind == op::destroy)
            w.destroy(target);
        else if (w.alive(target))
            c.apply(w, target, m_payload.data() + c.payload);
    }
    clear();
}

void command_buffer::clear() {
    m_commands.clear();
    m_payload.clear();
    m_placeholders = 0;
}

}  // namespace sylva::ecs
