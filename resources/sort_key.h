#pragma once
// 64-bit draw sort keys (the bgfx/Filament pattern): draw items are built in parallel, sorted
// by key with a stable radix sort, and the submission changes state only where the key's upper
// fields change. Items that share pass and mesh become one instanced indirect draw.
//
//   63     60  59   58              43 42                      19 18          8 7          0
//  +---------+-------+------------------+-------------------------+-------------+------------+
//  | pass  4 |faded 1|   mesh id  16    |  depth 24 (front first)  |  unused 11  | last fade 8|
//  +---------+-------+------------------+-------------------------+-------------+------------+
//
// Depth is the camera distance quantised logarithmically, so instances inside a batch are drawn
// front to back (early depth rejection on a software rasteriser is worth a lot). `faded` marks
// the partner of a transition that dissolves by the screen door: its batches are drawn by the
// dissolving programs, after the whole plants of the pass (program_table pass_kind::view_faded).
#include <cmath>
#include <cstdint>

namespace sylva {

enum class render_pass : std::uint8_t {
    shadow_cascade_0 = 0,
    shadow_cascade_1,
    shadow_cascade_2,
    shadow_cascade_3,
    opaque,
    count
};
constexpr int k_max_shadow_cascades = 4;

inline constexpr render_pass shadow_pass(int cascade) {
    return static_cast<render_pass>(static_cast<int>(render_pass::shadow_cascade_0) + cascade);
}
inline constexpr bool is_shadow_pass(render_pass p) { return p < render_pass::opaque; }

struct sort_key_fields {
    render_pass pass = render_pass::opaque;
    std::uint16_t mesh = 0;
    std::uint32_t depth = 0;  // 24 bits
    bool faded = false;
};

constexpr int k_pass_shift = 60;
constexpr int k_faded_shift = 59;
constexpr int k_mesh_shift = 43;
constexpr int k_depth_shift = 19;
constexpr std::uint32_t k_depth_max = (1u << 24) - 1;
static_assert(static_cast<int>(render_pass::count) <= 16, "pass must fit in 4 bits");
static_assert(k_pass_shift - k_faded_shift == 1 && k_faded_shift - k_mesh_shift == 16 &&
              k_mesh_shift - k_depth_shift == 24 && k_depth_shift >= 8);

constexpr std::uint64_t make_sort_key(const sort_key_fields& f) {
    return (std::uint64_t(f.pass) << k_pass_shift) | (std::uint64_t(f.faded) << k_faded_shift) |
           (std::uint64_t(f.mesh) << k_mesh_shift) | (std::uint64_t(f.depth & k_depth_max) << k_depth_shift);
}
constexpr sort_key_fields decode_sort_key(std::uint64_t key) {
    return {static_cast<render_pass>(key >> k_pass_shift),
            static_cast<std::uint16_t>((key >> k_mesh_shift) & 0xFFFFu),
            static_cast<std::uint32_t>((key >> k_depth_shift) & k_depth_max),
            ((key >> k_faded_shift) & 1u) != 0};
}
// The low byte is not a sort field: it carries a soft-splat prefix's point_prefix::last_fade
// from the plant to its instance record (build_draw_list), 0 for every other item.
constexpr std::uint64_t k_last_fade_mask = 0xFFu;
// Pass, faded and mesh: items with equal batch bits are drawn by one instanced command.
constexpr std::uint64_t batch_bits(std::uint64_t key) { return key >> k_mesh_shift; }

// Distance (metres) to 24-bit depth: log2 spacing between 0.1 m and ~100 km keeps relative
// precision constant; closer or farther saturate.
inline std::uint32_t quantize_depth(float distance_m) {
    constexpr float k_min = 0.1f;
    constexpr float k_log_range = 20.0f;  // log2(100 km / 0.1 m) ~ 19.9
    float t = distance_m > k_min ? std::log2(distance_m / k_min) / k_log_range : 0.0f;
    t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
    return static_cast<std::uint32_t>(t * float(k_depth_max));
}

}  // namespace sylva
