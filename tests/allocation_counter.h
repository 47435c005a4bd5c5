#pragma once
// Counts heap allocations made through the global operator new, on any thread, while a
// counting_allocations scope is open (STYLE habit 5: no allocation in the warm frame loop).
//
// Including this header REPLACES the global operator new and delete of the whole program, so
// include it in exactly one translation unit of a test binary of its own.
//
// What it sees: every C++ allocation (containers, strings, make_unique, std::function), ours
// and that of C++ libraries (spdlog, nlohmann-json, oneTBB's C++ front end). What it does not
// see: malloc called from C code (Mesa's own memory), and oneTBB's task objects, which it
// allocates with its own cache-aligned allocator, not operator new.
//
// The GL driver's allocations are counted apart, not hidden: llvmpipe compiles shader and
// vertex-fetch variants with LLVM (C++) when a draw first meets a state, and its rasteriser
// threads keep their own memory -- all of it behind the GL calls we make, in code this project
// cannot change. An allocation is the driver's when a frame of its call stack lies in the GL
// driver's shared objects (k_driver_objects); counts().driver says how many there were.
//
// Where: the first k_max_sites allocations counted as ours keep their return addresses, so a
// failing test can print where they came from (link the binary with ENABLE_EXPORTS for symbol
// names).
#include <execinfo.h>
#include <link.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

namespace sylva::testing {

namespace allocation_detail {

inline constexpr int k_max_sites = 8;
inline constexpr int k_site_depth = 24;
// Deep enough to reach the GL entry point from inside LLVM's code generator.
inline constexpr int k_stack_depth = 256;
// Shared objects whose code is the GL driver (file names contain one of these).
inline constexpr const char* k_driver_objects[] = {"libOSMesa", "libgallium", "_dri.so",
                                                   "libGLX_mesa"};

struct site {
    void* frames[k_site_depth];
    int depth;
    std::size_t bytes;
};

struct address_range {
    std::uintptr_t begin;
    std::uintptr_t end;
};

inline std::atomic<bool> counting{false};
inline std::atomic<std::uint64_t> allocations{0};
inline std::atomic<std::uint64_t> bytes{0};
inline std::atomic<std::uint64_t> driver_allocations{0};
inline std::atomic<int> sites_taken{0};
inline site sites[k_max_sites];
inline address_range driver_ranges[64];
inline int driver_range_count = 0;
// backtrace() may allocate the first time it runs (it loads the unwinder): not counted.
inline thread_local bool in_backtrace = false;

// The executable segments of the driver's shared objects, found once before counting starts.
inline void find_driver_ranges() {
    driver_range_count = 0;
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void*) {
            bool driver = false;
            for (const char* name : k_driver_objects)
                driver = driver || (info->dlpi_name && std::strstr(info->dlpi_name, name));
            if (!driver) return 0;
            for (int i = 0; i < info->dlpi_phnum && driver_range_count < 64; ++i) {
                const ElfW(Phdr)& h = info->dlpi_phdr[i];
                if (h.p_type != PT_LOAD || !(h.p_flags & PF_X)) continue;
                const std::uintptr_t begin = info->dlpi_addr + h.p_vaddr;
                driver_ranges[driver_range_count++] = {begin, begin + h.p_memsz};
            }
            return 0;
        },
        nullptr);
}

inline bool in_driver(void* const* frames, int depth) {
    for (int f = 0; f < depth; ++f)
        for (int r = 0; r < driver_range_count; ++r)
            if (std::uintptr_t(frames[f]) >= driver_ranges[r].begin &&
                std::uintptr_t(frames[f]) < driver_ranges[r].end)
                return true;
    return false;
}

inline void record(std::size_t size) {
    if (!counting.load(std::memory_order_relaxed) || in_backtrace) return;
    void* frames[k_stack_depth];
    in_backtrace = true;
    const int depth = ::backtrace(frames, k_stack_depth);
    in_backtrace = false;
    if (in_driver(frames, depth)) {
        driver_allocations.fetch_add(1, std::memory_order_relaxed);
        return;
    }
    allocations.fetch_add(1, std::memory_order_relaxed);
    bytes.fetch_add(size, std::memory_order_relaxed);
    const int slot = sites_taken.fetch_add(1, std::memory_order_relaxed);
    if (slot >= k_max_sites) return;
    sites[slot].depth = std::min(depth, k_site_depth);
    std::memcpy(sites[slot].frames, frames, sizeof(void*) * std::size_t(sites[slot].depth));
    sites[slot].bytes = size;
}

inline void* allocate(std::size_t size, std::size_t alignment, bool nothrow) {
    record(size);
    void* p = alignment > alignof(std::max_align_t)
                  ? std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment)
                  : std::malloc(size ? size : 1);
    if (!p && !nothrow) throw std::bad_alloc();
    return p;
}

}  // namespace allocation_detail

struct allocation_counts {
    std::uint64_t allocations = 0;  // outside the GL driver: what the test expects to be 0
    std::uint64_t bytes = 0;
    std::uint64_t driver = 0;  // beneath a GL call, in the driver (see above)
};

// Counts from construction to counts(); one scope at a time.
class counting_allocations {
public:
    counting_allocations() {
        allocation_detail::find_driver_ranges();
        allocation_detail::allocations = 0;
        allocation_detail::driver_allocations = 0;
        allocation_detail::bytes = 0;
        allocation_detail::sites_taken = 0;
        allocation_detail::counting = true;
    }
    ~counting_allocations() { allocation_detail::counting = false; }
    counting_allocations(const counting_allocations&) = delete;
    counting_allocations& operator=(const counting_allocations&) = delete;

    // Stops counting and returns what was counted.
    allocation_counts stop() {
        allocation_detail::counting = false;
        return {allocation_detail::allocations.load(), allocation_detail::bytes.load(),
                allocation_detail::driver_allocations.load()};
    }
    // The call stacks of the first allocations counted, to stderr (no allocation).
    static void print_sites() {
        const int n =
            std::min(allocation_detail::sites_taken.load(), allocation_detail::k_max_sites);
        for (int i = 0; i < n; ++i) {
            const auto& s = allocation_detail::sites[i];
            std::fprintf(stderr, "allocation %d of %zu bytes at:\n", i + 1, s.bytes);
            std::fflush(stderr);
            ::backtrace_symbols_fd(s.frames, s.depth, STDERR_FILENO);
        }
    }
};

}  // namespace sylva::testing

// The replacements (C++20 [new.delete]): every form forwards to malloc / aligned_alloc / free.
void* operator new(std::size_t n) {
    return sylva::testing::allocation_detail::allocate(n, 0, false);
}
void* operator new[](std::size_t n) {
    return sylva::testing::allocation_detail::allocate(n, 0, false);
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    return sylva::testing::allocation_detail::allocate(n, 0, true);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    return sylva::testing::allocation_detail::allocate(n, 0, true);
}
void* operator new(std::size_t n, std::align_val_t a) {
    return sylva::testing::allocation_detail::allocate(n, std::size_t(a), false);
}
void* operator new[](std::size_t n, std::align_val_t a) {
    return sylva::testing::allocation_detail::allocate(n, std::size_t(a), false);
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return sylva::testing::allocation_detail::allocate(n, std::size_t(a), true);
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return sylva::testing::allocation_detail::allocate(n, std::size_t(a), true);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    std::free(p);
}
