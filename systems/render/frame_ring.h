#pragma once
// Per-frame data (instances, indirect commands, uniforms) goes through one persistently mapped,
// coherent buffer split into `frames_in_flight` regions. Each region is fenced when its frame is
// submitted and waited on before it is written again, so the CPU never overwrites data the GPU
// still reads, and nothing is re-allocated in the frame loop once the ring is large enough.
#include <cstddef>
#include <cstdint>

#include "systems/render/gl_objects.h"

namespace sylva::render {

class frame_ring {
public:
    explicit frame_ring(std::size_t bytes_per_frame, int frames_in_flight = 3);
    ~frame_ring();
    frame_ring(const frame_ring&) = delete;
    frame_ring& operator=(const frame_ring&) = delete;

    // Waits for the GPU to release the next region; grows every region (waiting for the GPU to
    // go idle) when `bytes_needed` exceeds it.
    void begin_frame(std::size_t bytes_needed);
    struct allocation {
        void* data = nullptr;
        GLintptr offset = 0;  // from the start of buffer()
        std::size_t size = 0;
    };
    // Aligned sub-allocation inside this frame's region; throws if the frame overflows it.
    allocation allocate(std::size_t bytes, std::size_t alignment = 256);
    void end_frame();  // fences the region

    GLuint buffer() const { return m_buffer.id(); }
    std::size_t bytes_per_frame() const { return m_region_bytes; }
    std::size_t bytes_used_this_frame() const { return m_cursor; }

private:
    void create(std::size_t region_bytes);
    void release();

    gl_buffer m_buffer;
    std::byte* m_mapped = nullptr;
    std::size_t m_region_bytes = 0;
    int m_frames = 3;
    int m_region = 0;
    std::size_t m_cursor = 0;
    GLsync m_fences[8] = {};
};

}  // namespace sylva::render
