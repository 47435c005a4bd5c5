#include "resources/draw_list.h"

#include <algorithm>

#include "resources/scene_assets.h"

namespace sylva {

void radix_sort_draw_items(std::vector<draw_item>& items, std::vector<draw_item>& scratch) {
    const std::size_t n = items.size();
    if (n < 2) return;
    scratch.resize(n);
    std::uint64_t all_or = 0;
    std::uint64_t all_and = ~std::uint64_t(0);
    for (const auto& item : items) {
        all_or |= item.key;
        all_and &= item.key;
    }
    const std::uint64_t varying = all_or ^ all_and;  // bits that differ between some keys
    draw_item* src = items.data();
    draw_item* dst = scratch.data();
    for (int shift = 0; shift < 64; shift += 8) {
        if (((varying >> shift) & 0xFFu) == 0) continue;
        std::array<std::size_t, 257> offsets{};
        for (std::size_t i = 0; i < n; ++i) ++offsets[((src[i].key >> shift) & 0xFFu) + 1];
        for (std::size_t b = 1; b < offsets.size(); ++b) offsets[b] += offsets[b - 1];
        for (std::size_t i = 0; i < n; ++i) dst[offsets[(src[i].key >> shift) & 0xFFu]++] = src[i];
        std::swap(src, dst);
    }
    if (src != items.data()) std::copy(src, src + n, items.data());
}

void build_batches(draw_list& list, const species_library& library) {
    list.batches.clear();
    list.instances_by_representation.fill(0);
    list.triangles = list.shadow_triangles = list.points = list.lines = 0;
    const std::size_t n = list.items.size();
    for (std::size_t first = 0; first < n;) {
        const std::uint64_t bits = batch_bits(list.items[first].key);
        const std::uint32_t primitives = list.items[first].count;
        std::size_t last = first + 1;
        while (last < n && batch_bits(list.items[last].key) == bits && list.items[last].count == primitives) ++last;
        const sort_key_fields f = decode_sort_key(list.items[first].key);
        const auto count = std::uint32_t(last - first);
        list.batches.push_back({f.pass, f.mesh, std::uint32_t(first), count, primitives, f.faded});
        const mesh_info& mesh = library.meshes.at(f.mesh);
        const std::uint64_t drawn = std::uint64_t(primitives ? primitives : mesh.triangles) * count;
        if (f.pass != render_pass::opaque) {
            if (mesh.primitive == primitive_kind::triangles) list.shadow_triangles += drawn;
        } else {
            switch (mesh.primitive) {
                case primitive_kind::triangles: list.triangles += drawn; break;
                case primitive_kind::points: list.points += drawn; break;
                case primitive_kind::lines: list.lines += drawn; break;
            }
            // A plant drawn as point/line prefixes has several items; build_draw_list counts it.
            if (mesh.drawn_as != representation::points)
                list.instances_by_representation[static_cast<std::size_t>(mesh.drawn_as)] += count;
        }
        first = last;
    }
}

}  // namespace sylva
