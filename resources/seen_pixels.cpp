#include "resources/seen_pixels.h"

#include "resources/sort_key.h"
#include "setup/tile_point_sets.h"

#include <algorithm>

namespace sylva {

void count_seen_pixels(std::span<const std::uint32_t> ids, const draw_list& draws, seen_pixels& out) {
    std::fill(out.by_plant.begin(), out.by_plant.end(), 0u);
    std::fill(out.in_view.begin(), out.in_view.end(), std::uint8_t(0));
    for (const draw_item& item : draws.items) {
        if (is_shadow_pass(decode_sort_key(item.key).pass) || (item.instance & k_tile_item_bit)) continue;
        const std::uint32_t plant = item.instance & ~k_partner_item_bit;
        if (plant >= out.in_view.size()) out.in_view.resize(std::size_t(plant) + 1, 0);
        out.in_view[plant] = 1;
    }
    for (const std::uint32_t id : ids) {
        const std::uint32_t instance = instance_of_id(id, draws);
        if (instance == k_no_draw_item || (instance & k_tile_item_bit)) continue;  // nothing, or the terrain
        const std::uint32_t plant = instance & ~k_partner_item_bit;
        if (plant >= out.by_plant.size()) out.by_plant.resize(std::size_t(plant) + 1, 0u);
        ++out.by_plant[plant];
    }
    out.measured = true;
}

}  // namespace sylva
