#pragma once
// How many GL objects are alive in the current context, by kind, asked of the driver itself
// (glIs* over the name range), not counted by Sylva's own wrappers: a leak through a raw
// glCreate* call or a library that bypasses systems/render/gl_objects.h shows up too. The soak
// test (tests/stress/soak_stress_test.cpp) checks the total stays flat over thousands of frames.
//
// Mesa (like every driver Sylva runs on) hands out the lowest free name, so live names are dense
// from 1; the scan stops after k_census_gap unused names in a row. Sync objects are pointers,
// not names, and are left out (systems/render/frame_ring.cpp deletes each fence it waits for).
#include <cstddef>
#include <string>

namespace sylva::render {

inline constexpr unsigned k_census_gap = 4096;

struct gl_object_census {
    std::size_t buffers = 0;
    std::size_t textures = 0;
    std::size_t vertex_arrays = 0;
    std::size_t framebuffers = 0;
    std::size_t renderbuffers = 0;
    std::size_t programs = 0;
    std::size_t shaders = 0;
    std::size_t queries = 0;
    std::size_t samplers = 0;

    std::size_t total() const {
        return buffers + textures + vertex_arrays + framebuffers + renderbuffers + programs +
               shaders + queries + samplers;
    }
    std::string describe() const;  // "buffers 12, textures 30, ..."
    bool operator==(const gl_object_census&) const = default;
};

// Needs a current GL context; call on the thread that owns it.
gl_object_census take_gl_object_census();

}  // namespace sylva::render
