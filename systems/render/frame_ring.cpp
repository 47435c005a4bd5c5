#include "systems/render/frame_ring.h"

#include <stdexcept>
#include <string>

namespace sylva::render {
namespace {

constexpr GLbitfield k_map_flags = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;

void wait_and_delete(GLsync& fence) {
    if (!fence) return;
    while (glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000) == GL_TIMEOUT_EXPIRED) {
    }
    glDeleteSync(fence);
    fence = nullptr;
}

}  // namespace

frame_ring::frame_ring(std::size_t bytes_per_frame, int frames_in_flight) : m_frames(frames_in_flight) {
    if (m_frames < 1 || m_frames > 8) throw std::invalid_argument("frame_ring: 1..8 frames in flight");
    create(bytes_per_frame);
}

frame_ring::~frame_ring() { release(); }

void frame_ring::create(std::size_t region_bytes) {
    m_region_bytes = (region_bytes + 255) & ~std::size_t(255);
    m_buffer = make_buffer();
    const auto total = GLsizeiptr(m_region_bytes * std::size_t(m_frames));
    glNamedBufferStorage(m_buffer.id(), total, nullptr, k_map_flags);
    m_mapped = static_cast<std::byte*>(glMapNamedBufferRange(m_buffer.id(), 0, total, k_map_flags));
    if (!m_mapped) throw std::runtime_error("frame_ring: cannot map the persistent buffer");
}

void frame_ring::release() {
    for (auto& fence : m_fences) wait_and_delete(fence);
    if (m_buffer) glUnmapNamedBuffer(m_buffer.id());
    m_buffer.reset();
    m_mapped = nullptr;
}

void frame_ring::begin_frame(std::size_t bytes_needed) {
    m_region = (m_region + 1) % m_frames;
    if (bytes_needed > m_region_bytes) {
        release();  // waits for every region, then re-creates them larger
        create(bytes_needed + bytes_needed / 2);
    }
    wait_and_delete(m_fences[m_region]);
    m_cursor = 0;
}

frame_ring::allocation frame_ring::allocate(std::size_t bytes, std::size_t alignment) {
    std::size_t start = (m_cursor + alignment - 1) / alignment * alignment;
    if (start + bytes > m_region_bytes)
        throw std::runtime_error("frame_ring: frame needs more than the " +
                                 std::to_string(m_region_bytes) + " bytes reserved in begin_frame");
    m_cursor = start + bytes;
    std::size_t offset = std::size_t(m_region) * m_region_bytes + start;
    return {m_mapped + offset, GLintptr(offset), bytes};
}

void frame_ring::end_frame() {
    m_fences[m_region] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

}  // namespace sylva::render
