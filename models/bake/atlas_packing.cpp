#include "models/bake/atlas_packing.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <string>

namespace {

// qsort's interface with std::stable_sort underneath: stb_rect_pack sorts by height (then width)
// and qsort may order equal keys either way, which would move equal-sized rectangles around.
void stable_qsort(void* base, std::size_t count, std::size_t size, int (*compare)(const void*, const void*)) {
    auto* bytes = static_cast<std::byte*>(base);
    std::vector<std::byte> copy(bytes, bytes + count * size);
    std::vector<std::size_t> order(count);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return compare(copy.data() + a * size, copy.data() + b * size) < 0;
    });
    for (std::size_t i = 0; i < count; ++i) std::memcpy(bytes + i * size, copy.data() + order[i] * size, size);
}

}  // namespace

#define STBRP_SORT stable_qsort
#define STB_RECT_PACK_IMPLEMENTATION
#define STBRP_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_rect_pack.h>
#pragma GCC diagnostic pop

namespace sylva {

std::optional<std::vector<atlas_rect>> pack_atlas(std::span<const glm::uvec2> sizes, std::uint32_t width,
                                                  std::uint32_t height, std::uint32_t gutter) {
    constexpr std::uint32_t k_max_side = 1u << 24;
    if (width == 0 || height == 0 || width > k_max_side || height > k_max_side)
        throw std::invalid_argument("pack_atlas: atlas " + std::to_string(width) + " x " + std::to_string(height) +
                                    " is empty or wider than 2^24 texels");
    for (std::size_t i = 0; i < sizes.size(); ++i)
        if (sizes[i].x == 0 || sizes[i].y == 0 || sizes[i].x > k_max_side || sizes[i].y > k_max_side)
            throw std::invalid_argument("pack_atlas: rectangle " + std::to_string(i) + " is " +
                                        std::to_string(sizes[i].x) + " x " + std::to_string(sizes[i].y));
    if (sizes.empty()) return std::vector<atlas_rect>{};
    if (width <= gutter || height <= gutter) return std::nullopt;
    // Each rectangle is packed with a gutter on its right and bottom into an atlas shrunk by one
    // gutter, then everything moves one gutter right and down: gutters between all of them and
    // along every border.
    const int inner_width = int(width - gutter);
    std::vector<stbrp_node> nodes(static_cast<std::size_t>(inner_width));
    stbrp_context context;
    stbrp_init_target(&context, inner_width, int(height - gutter), nodes.data(), int(nodes.size()));
    std::vector<stbrp_rect> rects(sizes.size());
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        rects[i].id = int(i);
        rects[i].w = int(sizes[i].x + gutter);
        rects[i].h = int(sizes[i].y + gutter);
    }
    if (!stbrp_pack_rects(&context, rects.data(), int(rects.size()))) return std::nullopt;
    std::vector<atlas_rect> out(sizes.size());
    for (const stbrp_rect& r : rects)
        out[std::size_t(r.id)] = {std::uint32_t(r.x) + gutter, std::uint32_t(r.y) + gutter, sizes[std::size_t(r.id)].x,
                                  sizes[std::size_t(r.id)].y};
    return out;
}

bool overlaps(const atlas_rect& a, const atlas_rect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

}  // namespace sylva
