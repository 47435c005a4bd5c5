#include "app/drawn_mix.h"

#include "components/fade_alpha.h"
#include "components/lod_state.h"
#include "components/octree_cell.h"
#include "components/plant_instance.h"
#include "components/point_prefix.h"
#include "components/tile.h"
#include "systems/aggregate_eco_tiles_system.h"
#include "resources/scene_assets.h"
#include "setup/tile_point_sets.h"
#include "systems/update_point_prefix_system.h"

namespace sylva {
namespace {

// Triangles of `parts` drawn as triangles, of all their triangles, and line parts drawn as
// splats, added to the running totals.
void add_prefix(const species_library& library, part_range parts, const point_prefix& prefix,
                double& drawn, double& total, std::uint16_t& splat_parts) {
    for (std::uint32_t i = 0; i < parts.count && i < k_prefix_parts; ++i) {
        const lod_part_entry& part = library.lod_parts[parts.first + i];
        drawn += double(prefix.triangles[i]);
        total += double(part.triangle_count);
        if (prefix.splats[i]) ++splat_parts;
    }
}

}  // namespace

void read_drawn_mixes(const ecs::world& world, std::vector<drawn_mix>& out) {
    const auto& lods = world.table<lod_state>();
    const auto& fades = world.table<fade_alpha>();
    const auto& prefixes = world.table<point_prefix>();
    const std::size_t n = lods.size();
    out.assign(n, drawn_mix{});
    const species_library* library = world.try_resource<species_library>();
    std::vector<double> drawn(n, 0.0), total(n, 0.0);
    std::vector<std::uint16_t> splat_parts(n, 0);
    for (std::size_t k = 0; k < n; ++k) {
        const lod_state& lod = lods.data()[k];
        drawn_mix& m = out[k];
        m.group_first = std::uint32_t(k);
        m.primary = std::uint8_t(lod.current);
        if (k < fades.size() && fades.data()[k].partner != representation::none &&
            fades.data()[k].value > 0.0f) {
            m.partner = std::uint8_t(fades.data()[k].partner);
            m.share = fades.data()[k].value;
        }
        if (lod.current == representation::points && library && k < prefixes.size()) {
            const auto& species = library->species[static_cast<std::size_t>(
                world.table<plant_instance>().data()[k].species)];
            add_prefix(*library, parts_of(species), prefixes.data()[k], drawn[k], total[k],
                       splat_parts[k]);
        }
    }
    // §6.1: a big plant's octree cells carry its parts.
    if (library) {
        const auto& cells = world.table<octree_cell>();
        const auto& cell_prefixes = world.table<cell_prefix>();
        for (std::size_t c = 0; c < cells.size() && c < cell_prefixes.size(); ++c) {
            const octree_cell& cell = cells.data()[c];
            if (cell.plant >= n || lods.data()[cell.plant].current != representation::points)
                continue;
            add_prefix(*library, parts_of(library->cells[cell.cell]),
                       cell_prefixes.data()[c].prefix, drawn[cell.plant], total[cell.plant],
                       splat_parts[cell.plant]);
        }
    }
    for (std::size_t k = 0; k < n; ++k)
        if (out[k].primary == std::uint8_t(representation::points)) {
            out[k].share = total[k] > 0.0 ? float(drawn[k] / total[k]) : 0.0f;
            out[k].detail = splat_parts[k];
        }
    // §6.2: the plants of a tile drawn as its sets (aggregate_eco_tiles put them on the eco_tile rung).
    const auto* sets = world.try_resource<tile_point_sets>();
    const auto* draws = world.try_resource<tile_point_draws>();
    if (!sets || !draws) return;
    const auto& tiles = world.table<tile>();
    for (std::size_t p = 0; p < draws->counts.size() && p < sets->parts.size(); ++p) {
        if (draws->counts[p] == 0) continue;
        const tile& t = tiles.data()[sets->parts[p].tile];
        for (std::uint32_t k = t.first_plant; k < t.first_plant + t.plant_count && k < n; ++k) {
            drawn_mix& m = out[k];
            // A plant in a tile's band keeps its points partner (the share the tile leaves it).
            const drawn_mix own = m;
            m = {};
            m.partner = own.partner;
            m.share = own.partner != 0 ? own.share : 0.0f;
            m.primary = k_mix_eco_tile_set;
            m.group_first = t.first_plant;
            m.group_count = t.plant_count;
        }
    }
}

const char* transition_kind(const transition_window& w) {
    if (w.grouped) return "eco_tile_set";
    if (w.partnered) return "fade";
    if (w.from.primary != w.to.primary) return "switch";
    return "blend";
}

}  // namespace sylva
