#include "systems/build_draw_list_system.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "ecs/parallel.h"
#include "lod/lodf.h"
#include "systems/update_point_prefix_system.h"

namespace sylva {
namespace {


// What one plant contributes: a bit per pass it is drawn in, and its mesh in each pass. Each
// shadow cascade draws the plant one mesh level coarser than the one before it (cascade 0 as
// the view does): a farther cascade's texel is larger than the detail the finer mesh adds. A
// rung whose ladder names a caster (ladder::shadow) casts as that rung instead.
//
// A plant drawn as points and lines (Deussen 2002 §5.3) is instead up to two prefixes per part,
// its first triangles and its first points or lines, the same in every pass it is drawn in.
// No member initialisers: plant_draws leaves its prefix slots uninitialised (only the first
// prefix_count of each pass are written and read), because zeroing 320 bytes twice per plant
// was most of build_draw_list's time with a million plants.
struct prefix_draw {
    std::uint16_t mesh;
    std::uint8_t last_fade;  // point_prefix::last_fade
    std::uint32_t count;
};
// In a shadow cascade the prefixes are the cascade's own: its texel is the sample distance there.
constexpr std::size_t k_passes = std::size_t(render_pass::count);
struct plant_draws {
    std::array<std::uint16_t, k_passes> mesh{};
    std::array<std::array<prefix_draw, 2 * k_prefix_parts>, k_passes> prefixes;  // [0, prefix_count) set
    std::array<std::uint32_t, k_passes> prefix_count{};
    bool prefixed = false;       // drawn as prefixes (`prefixes`), else one whole mesh per pass
    // The opaque pass also draws the fade_alpha partner: `partner_mesh`, or when the partner is
    // points and lines its own prefixes (`partner_prefixes`, the first `fade` of the primary's).
    bool partnered = false;
    bool partner_prefixed = false;
    bool partner_dissolves = false;  // a mesh or crossed billboard: the screen door (sort_key.h faded)
    std::uint16_t partner_mesh = 0;
    std::uint32_t partner_prefix_count = 0;
    std::array<prefix_draw, 2 * k_prefix_parts> partner_prefixes;  // [0, partner_prefix_count) set
    std::uint32_t pass_mask = 0;  // bit i: render_pass i
    float distance = 0.0f;

    std::uint32_t items_in(std::size_t pass) const { return prefixed ? prefix_count[pass] : 1u; }
    std::uint32_t partner_items() const { return !partnered ? 0u : partner_prefixed ? partner_prefix_count : 1u; }
    std::uint32_t items() const {
        std::uint32_t n = partner_items();
        for (std::uint32_t mask = pass_mask; mask; mask &= mask - 1) n += items_in(std::size_t(__builtin_ctz(mask)));
        return n;
    }
};

std::uint16_t mesh_of(const species_entry& species, representation r) {
    switch (r) {
        case representation::mesh_full: return species.mesh_full;
        case representation::mesh_reduced: return species.mesh_reduced;
        case representation::crossed_billboard: return species.mesh_billboard;
        case representation::facing_billboard: return species.mesh_facing;
        case representation::billboard_cloud: return species.mesh_cloud;
        // The trunk and branches; the foliage is drawn by its slot's commands.
        case representation::lodf: return species.mesh_lodf_bark;
        default: return species.mesh_far;
    }
}

// The mesh representation `steps` levels coarser than `r`, stopping at the far mesh. Other
// representations are not mesh levels and cast shadows as themselves.
representation coarser(representation r, int steps) {
    if (r < representation::mesh_full || r > representation::mesh_far) return r;
    return static_cast<representation>(std::min(int(r) + steps, int(representation::mesh_far)));
}

class draw_builder {
public:
    draw_builder(const camera& cam, const species_library& library, const cascade_set& cascades,
                 const lod_policy& policy, const primitive_costs& costs)
        : m_camera(cam),
          m_library(library),
          m_cascade_set(cascades),
          m_sample_distance(image_plane_units(policy.points.sample_distance_px, cam.fov_y,
                                              cam.viewport_height_px)),
          m_costs(costs),
          m_cascades(cascade_boxes(cascades)),
          m_cascade_count(cascades.count),
          m_ladders(policy.ladders) {}

    // The passes a plant is drawn in: the view's when it is visible, and each shadow cascade its
    // bounding sphere overlaps when it is in shadow range.
    std::uint32_t passes_of(const world_transform& t, const bounds& b, const lod_state& lod) const {
        std::uint32_t mask = 0;
        const glm::vec3 center = glm::vec3(t.position - m_camera.position) + glm::vec3(0.0f, b.center_height, 0.0f);
        if (lod.visible) mask |= 1u << unsigned(render_pass::opaque);
        if (lod.in_shadow_range)
            for (int c = 0; c < m_cascade_count; ++c)
                if (sphere_overlaps_cascade(m_cascades[std::size_t(c)], center, b.radius))
                    mask |= 1u << unsigned(shadow_pass(c));
        return mask;
    }

    // `parts` are the plant's point/line parts, or one octree cell's (§6.1), whose prefixes
    // `prefix` holds; a split plant itself has none (its cells are classified one by one).
    plant_draws classify(const world_transform& t, const bounds& b, const plant_instance& p,
                         const lod_state& lod, const fade_alpha& fade, const point_prefix& prefix,
                         part_range parts) const {
        plant_draws d;
        if (lod.current == representation::none) return d;
        const auto& species = m_library.species[static_cast<std::size_t>(p.species)];
        const glm::vec3 base{t.position - m_camera.position};
        d.distance = glm::length(base);
        d.pass_mask = passes_of(t, b, lod);
        // Behrendt 2005 §2.3: the partner is drawn in the view only, faded (select_representation
        // only names one for a visible plant); the primary alone casts.
        // Behrendt 2005 §3.3 end: a shell partner is the shell pass's, fading in by distance.
        if (lod.visible && fade.partner != representation::none && fade.partner != representation::shell &&
            fade.value > 0.0f) {
            if (fade.partner == representation::points) add_partner_prefixes(parts, prefix, fade.value, d);
            else d.partner_mesh = mesh_of(species, fade.partner);
            d.partnered = true;
            d.partner_prefixed = fade.partner == representation::points;
            // A billboard cloud fades by its own threshold (cloud.frag), points by their prefix.
            d.partner_dissolves = !d.partner_prefixed && fade.partner != representation::billboard_cloud;
        }
        // Drawn by its eco tile's sets (aggregate_eco_tiles): only the partner, its own prefixes
        // for the share the tile does not draw; nothing casts (the tile lies beyond the shadows).
        // Drawn by the shell textures over its terrain: only the partner, faded (nothing casts:
        // the shells receive the sun's shadows but cast none).
        if (lod.current == representation::eco_tile || lod.current == representation::shell) {
            d.pass_mask = 0;
            return d;
        }
        if (lod.current != representation::points) {
            d.mesh[std::size_t(render_pass::opaque)] = mesh_of(species, lod.current);
            // The rung's caster when its ladder names one (ladder::shadow), else the rung itself.
            const auto k = static_cast<std::size_t>(p.species);
            // (A walk over at most 8 rungs; a per-species table built here would allocate every
            // frame, which the warm frame must not.)
            const representation caster = k < m_ladders.size() ? m_ladders[k].caster_of(lod.current) : lod.current;
            // LoDF's foliage casts into cascade 0 alone, as the view draws it (its slot's pass
            // mask, build_draw_list_system below); each farther cascade casts the mesh level the
            // full mesh would there. LoDF whole is the full mesh, so at its top the plant casts
            // the full mesh's shadow in every cascade and the switch into it changes no shadow.
            for (int c = 0; c < m_cascade_count; ++c) {
                const representation cast_as =
                    caster == representation::lodf && c > 0 ? representation::mesh_full : caster;
                d.mesh[std::size_t(shadow_pass(c))] = mesh_of(species, coarser(cast_as, m_camera.full_geometry ? 0 : c));
            }
            return d;
        }
        d.prefixed = true;
        add_prefixes(parts, prefix, d, render_pass::opaque);
        // A cascade samples the plant every k_shadow_sample_texels texels, but never finer than
        // k_shadow_sample_spacing times the viewer's sample distance there (d'·r): its shadow
        // lands about as far away as the plant stands. Only the cascades the plant casts into.
        const double seen_m = k_shadow_sample_spacing * m_sample_distance * double(d.distance);
        for (int c = 0; c < m_cascade_count; ++c) {
            if (!(d.pass_mask & (1u << unsigned(shadow_pass(c))))) continue;
            const double texel =
                std::max(k_shadow_sample_texels * double(m_cascade_set.texel_world_size[std::size_t(c)]), seen_m);
            add_prefixes(parts, compute_shadow_prefix(m_library, parts, t.scale, texel, m_costs), d,
                         shadow_pass(c));
        }
        return d;
    }

    // A split plant's cell whose plant fades its points in as a partner: only the partner's
    // prefixes, in the opaque pass (the plant's own items draw its primary).
    plant_draws classify_partner_cell(const world_transform& t, const lod_state& lod, const fade_alpha& fade,
                                      const point_prefix& prefix, part_range parts) const {
        plant_draws d;
        if (!lod.visible || fade.partner != representation::points || !(fade.value > 0.0f)) return d;
        d.distance = glm::length(glm::vec3(t.position - m_camera.position));
        d.partnered = d.partner_prefixed = true;
        add_partner_prefixes(parts, prefix, fade.value, d);
        return d;
    }

private:
    // Deussen 2002 §5.3's prefix blend as a fade: the first `fade` of each prefix. Its triangles
    // and samples are in random order, so the thinning is uniform over the part.
    void add_partner_prefixes(part_range parts, const point_prefix& prefix, float fade, plant_draws& d) const {
        const auto share = [fade](std::uint32_t n) { return std::uint32_t(double(n) * double(fade) + 0.5); };
        for (std::uint32_t i = 0; i < parts.count && i < k_prefix_parts; ++i) {
            const lod_part_entry& part = m_library.lod_parts[parts.first + i];
            if (const std::uint32_t n = share(prefix.triangles[i]))
                d.partner_prefixes[d.partner_prefix_count++] = {part.mesh_triangles, 0, n};
            if (const std::uint32_t n = share(prefix.primitives[i]))
                d.partner_prefixes[d.partner_prefix_count++] = {
                    prefix.splats[i] ? part.mesh_splats : part.mesh_primitives, 0, n};
        }
    }

    void add_prefixes(part_range parts, const point_prefix& prefix, plant_draws& d, render_pass pass) const {
        auto& list = d.prefixes[std::size_t(pass)];
        std::uint32_t& count = d.prefix_count[std::size_t(pass)];
        for (std::uint32_t i = 0; i < parts.count && i < k_prefix_parts; ++i) {
            const lod_part_entry& part = m_library.lod_parts[parts.first + i];
            if (prefix.triangles[i]) list[count++] = {part.mesh_triangles, 0, prefix.triangles[i]};
            if (prefix.primitives[i])
                list[count++] = {prefix.splats[i] ? part.mesh_splats : part.mesh_primitives,
                                 prefix.last_fade[i], prefix.primitives[i]};
        }
    }

    const camera& m_camera;
    const species_library& m_library;
    const cascade_set& m_cascade_set;
    double m_sample_distance = 0.0;  // d' on the image plane
    const primitive_costs& m_costs;
    std::array<cascade_bounds, k_max_cascades> m_cascades{};
    int m_cascade_count = 0;
    const std::vector<ladder>& m_ladders;  // a species' ladder may name what a rung casts as
};

instance_gpu make_instance(const camera& cam, const world_transform& t, const plant_instance& p,
                           const fade_alpha& fade, bool partner, const species_library& library) {
    instance_gpu g;
    g.position = glm::vec3(t.position - cam.position);
    g.yaw = t.yaw;
    g.scale = t.scale;
    g.tint = float(p.tint) / 65535.0f * 2.0f - 1.0f;
    g.fade = partner ? fade.value : 1.0f;  // the primary is drawn whole
    g.texture_layer = library.species[static_cast<std::size_t>(p.species)].texture_layer;
    return g;
}

}  // namespace

// Writes the items of one classified plant (or cell) for every pass it is drawn in.
draw_item* write_items(const plant_draws& d, std::uint32_t plant, draw_item* out) {
    const std::uint32_t depth = quantize_depth(d.distance);
    if (d.partnered && !d.partner_prefixed)
        *out++ = {make_sort_key({render_pass::opaque, d.partner_mesh, depth, d.partner_dissolves}),
                  plant | k_partner_item_bit, 0};
    for (std::uint32_t i = 0; d.partnered && i < d.partner_prefix_count; ++i)
        *out++ = {make_sort_key({render_pass::opaque, d.partner_prefixes[i].mesh, depth}),
                  plant | k_partner_item_bit, d.partner_prefixes[i].count};
    for (std::uint32_t mask = d.pass_mask; mask; mask &= mask - 1) {
        const auto pass = static_cast<render_pass>(__builtin_ctz(mask));
        if (!d.prefixed) {
            *out++ = {make_sort_key({pass, d.mesh[std::size_t(pass)], depth}), plant, 0};
            continue;
        }
        const auto& prefixes = d.prefixes[std::size_t(pass)];
        for (std::uint32_t i = 0; i < d.items_in(std::size_t(pass)); ++i)
            *out++ = {make_sort_key({pass, prefixes[i].mesh, depth}) | prefixes[i].last_fade, plant,
                      prefixes[i].count};
    }
    return out;
}

void build_draw_list_system::run(ecs::system_context<build_draw_list_system>& ctx) {
    const camera& cam = ctx.single<camera>();
    const auto& library = ctx.resource<species_library>();
    const draw_builder builder(cam, library, ctx.resource<cascade_set>(), ctx.resource<lod_policy>(),
                               ctx.resource<primitive_costs>());
    auto plants = ctx.query<const world_transform, const bounds, const plant_instance, const lod_state,
                            const fade_alpha, const point_prefix>();
    auto cells = ctx.query<const octree_cell, const cell_prefix>();
    const std::size_t n = plants.size();
    const std::size_t chunk = ctx.chunk();
    const std::size_t chunks = ecs::chunk_count(n, chunk);
    const std::size_t cell_chunks = ecs::chunk_count(cells.size(), chunk);
    draw_list& list = ctx.resource_mut<draw_list>();
    const auto transforms = ctx.read<world_transform>().data();
    const auto bounds_of = ctx.read<bounds>().data();
    const auto instances = ctx.read<plant_instance>().data();
    const auto lods = ctx.read<lod_state>().data();
    const auto fades = ctx.read<fade_alpha>().data();
    // Luft 2007 §5 (components/population_ambient.h): present, aligned with the plants, only when
    // a species asks for its population's darkening.
    const auto populations = ctx.read<population_ambient>().data();
    const bool has_population = ctx.read<population_ambient>().size() == n;
    // Rebollo 2006: a plant on the LoDF rung without a slot (resources/lodf_slots.h) is drawn
    // as mesh_full, its foliage at full detail; as a partner too.
    // (A world built without the LoDF slots, as unit tests build them, has none.)
    static const lodf_slots k_no_slots{};
    const lodf_slots* found_slots = ctx.try_resource<lodf_slots>();
    const lodf_slots& slots = found_slots ? *found_slots : k_no_slots;
    const auto slotted = [&](std::size_t plant, lod_state lod, fade_alpha& fade) {
        const bool has_slot = plant < slots.slot_of_plant.size() && slots.slot_of_plant[plant] != k_no_lodf_slot;
        if (!has_slot && lod.current == representation::lodf) lod.current = representation::mesh_full;
        if (!has_slot && fade.partner == representation::lodf) fade.partner = representation::mesh_full;
        return lod;
    };
    auto classify_cell = [&](const octree_cell& cell, const cell_prefix& prefix) {
        const std::size_t k = cell.plant;
        const part_range parts = parts_of(library.cells[cell.cell]);
        // A plant drawn any other way than as points is drawn whole, by the plant's own items,
        // and so is the partner of one drawn as points; a points partner is drawn by its cells.
        if (lods[k].current != representation::points)
            return builder.classify_partner_cell(transforms[k], lods[k], fades[k], prefix.prefix, parts);
        return builder.classify(transforms[k], bounds_of[k], instances[k], lods[k], fade_alpha{}, prefix.prefix,
                                parts);
    };

    // Pass 1: how many items each chunk adds (plant chunks, then octree-cell chunks).
    // Pass 2: write them at the prefix-sum offsets.
    std::vector<std::uint32_t>& offsets = list.chunk_offsets;
    offsets.assign(chunks + cell_chunks + 1, 0);
    std::vector<std::uint32_t>& point_plants = list.chunk_point_plants;
    point_plants.assign(chunks, 0);
    std::vector<std::uint32_t>& eco_plants = list.chunk_eco_plants;
    eco_plants.assign(chunks, 0);
    std::vector<std::uint32_t>& shell_plants = list.chunk_shell_plants;  // drawn by the shell pass
    shell_plants.assign(chunks, 0);
    ctx.parallel_for(n, chunk, [&](std::size_t begin, std::size_t end, std::size_t c) {
        std::uint32_t count = 0;
        std::size_t plant = begin;
        plants.each_chunk(begin, end, [&](ecs::entity, const world_transform& t, const bounds& b,
                                          const plant_instance& p, const lod_state& drawn, const fade_alpha& faded,
                                          const point_prefix& prefix) {
            const std::size_t i = plant++;
            // Most of a big scene is culled: skip those plants before touching their other
            // components (reading plant_instance for the species cost a cache line per plant).
            if (drawn.current == representation::none) return;
            fade_alpha fade = faded;
            const lod_state lod = slotted(i, drawn, fade);
            const species_entry& species = library.species[static_cast<std::size_t>(p.species)];
            count += builder.classify(t, b, p, lod, fade, prefix, parts_of(species)).items();
            // Counted as the meshes are (by their items): the primary and a drawn partner.
            const bool points_partner = fade.partner == representation::points && fade.value > 0.0f;
            if ((lod.current == representation::points || points_partner) && lod.visible) ++point_plants[c];
            if (lod.current == representation::eco_tile && lod.visible) ++eco_plants[c];
            if (lod.current == representation::shell && lod.visible) ++shell_plants[c];
        });
        offsets[c + 1] = count;
    });
    ctx.parallel_for(cells.size(), chunk, [&](std::size_t begin, std::size_t end, std::size_t c) {
        std::uint32_t count = 0;
        cells.each_chunk(begin, end, [&](ecs::entity, const octree_cell& cell, const cell_prefix& prefix) {
            count += classify_cell(cell, prefix).items();
        });
        offsets[chunks + c + 1] = count;
    });
    for (std::size_t c = 0; c < chunks + cell_chunks; ++c) offsets[c + 1] += offsets[c];
    // Far eco tiles drawn as their point and line sets (Deussen 2002 §6.2) come last.
    const tile_point_sets& tile_sets = ctx.resource<tile_point_sets>();
    const std::vector<std::uint32_t>& tile_counts = ctx.resource<tile_point_draws>().counts;
    const std::vector<std::uint8_t>& tile_splats = ctx.resource<tile_point_draws>().splats;
    std::size_t tile_items = 0;
    for (const std::uint32_t count : tile_counts) tile_items += count > 0;
    list.items.resize(offsets[chunks + cell_chunks] + tile_items);
    ctx.parallel_for(n, chunk, [&](std::size_t begin, std::size_t end, std::size_t c) {
        draw_item* out = list.items.data() + offsets[c];
        std::uint32_t index = std::uint32_t(begin);
        plants.each_chunk(begin, end, [&](ecs::entity, const world_transform& t, const bounds& b,
                                          const plant_instance& p, const lod_state& drawn, const fade_alpha& faded,
                                          const point_prefix& prefix) {
            const std::uint32_t plant = index++;
            if (drawn.current == representation::none) return;
            fade_alpha fade = faded;
            const lod_state lod = slotted(plant, drawn, fade);
            const species_entry& species = library.species[static_cast<std::size_t>(p.species)];
            out = write_items(builder.classify(t, b, p, lod, fade, prefix, parts_of(species)), plant, out);
        });
    });
    ctx.parallel_for(cells.size(), chunk, [&](std::size_t begin, std::size_t end, std::size_t c) {
        draw_item* out = list.items.data() + offsets[chunks + c];
        cells.each_chunk(begin, end, [&](ecs::entity, const octree_cell& cell, const cell_prefix& prefix) {
            out = write_items(classify_cell(cell, prefix), cell.plant, out);
        });
    });
    draw_item* tile_out = list.items.data() + offsets[chunks + cell_chunks];
    for (std::size_t i = 0; i < tile_counts.size(); ++i) {
        if (tile_counts[i] == 0) continue;
        const tile_point_part& part = tile_sets.parts[i];
        const auto depth = quantize_depth(float(glm::length(tile_sets.origin[part.tile] - cam.position)));
        const std::uint16_t mesh = i < tile_splats.size() && tile_splats[i] ? part.mesh_splats : part.mesh;
        *tile_out++ = {make_sort_key({render_pass::opaque, mesh, depth}), k_tile_item_bit | std::uint32_t(i),
                       tile_counts[i]};
    }
    radix_sort_draw_items(list.items, list.scratch);

    // Instance records in sorted order; the tables are aligned, so a dense index reads them all.
    list.instances.resize(list.items.size());
    ctx.parallel_for(list.items.size(), chunk, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint32_t k = list.items[i].instance;
            if (k & k_tile_item_bit) {
                const tile_point_part& part = tile_sets.parts[k & ~k_tile_item_bit];
                instance_gpu g;
                g.position = glm::vec3(tile_sets.origin[part.tile] - cam.position);
                g.texture_layer = part.texture_layer + k_aggregated_layer_flag;
                list.instances[i] = g;
                continue;
            }
            const bool partner = (k & k_partner_item_bit) != 0;
            const std::uint32_t plant = k & ~k_partner_item_bit;
            list.instances[i] = make_instance(cam, transforms[plant], instances[plant], fades[plant], partner, library);
            if (has_population) list.instances[i].population = populations[plant];
            // A points partner fades by its prefix (add_partner_prefixes): its triangles are
            // drawn whole, not also dissolved.
            if (partner && library.meshes[decode_sort_key(list.items[i].key).mesh].drawn_as == representation::points)
                list.instances[i].fade = 1.0f;
        }
        // Point prefixes: the fade is the fractional prefix length, so the soft-splat shader
        // draws splat j at opacity clamp(fade − j, 0, 1) (every splat whole but a faded last).
        for (std::size_t i = begin; i < end; ++i) {
            const draw_item& item = list.items[i];
            if (library.meshes[decode_sort_key(item.key).mesh].primitive != primitive_kind::points)
                continue;
            list.instances[i].fade =
                item.count == 0 ? 1e9f
                                : float(item.count) - float(item.key & k_last_fade_mask) / 255.0f;
        }
    });
    build_batches(list, library);
    // The LoDF slots' records: a plant on the rung is drawn whole, a partner faded (its trunk's
    // items above carry the same fade).
    list.lodf_instances.resize(slots.slots.size());
    list.lodf_plants.resize(slots.slots.size());
    list.lodf_pass_masks.resize(slots.slots.size());
    const cluster_changes* clusters = ctx.read<cluster_changes>().data();
    for (std::size_t s = 0; s < slots.slots.size(); ++s) {
        const lodf_slot& slot = slots.slots[s];
        instance_gpu& g = list.lodf_instances[s];
        g = instance_gpu{};
        list.lodf_plants[s] = slot.plant == k_no_lodf_slot ? k_no_draw_item : slot.plant;
        list.lodf_pass_masks[s] = 0;
        if (slot.plant == k_no_lodf_slot) {
            g.scale = 0.0f;
            continue;
        }
        const bool partner = lods[slot.plant].current != representation::lodf;
        g = make_instance(cam, transforms[slot.plant], instances[slot.plant], fades[slot.plant], partner, library);
        // Like every plant's items: the primary casts, a faded partner is drawn in the view only
        // (Behrendt 2005 §2.3), so a plant in a band casts once. The foliage casts into cascade 0
        // only; the farther cascades get the full mesh's coarser levels (classify).
        const std::uint32_t passes = builder.passes_of(transforms[slot.plant], bounds_of[slot.plant], lods[slot.plant]);
        const std::uint32_t view = 1u << unsigned(render_pass::opaque);
        list.lodf_pass_masks[s] = passes & (partner ? view : view | (1u << unsigned(shadow_pass(0))));
        if (has_population) g.population = populations[slot.plant];
        if (!lods[slot.plant].visible) continue;
        const lodf_structure& lodf = library.lodf[slot.species];
        for (std::uint32_t c = 0; c < lodf.clusters.size(); ++c)
            list.triangles += active_range(lodf, c, clusters[s * slots.clusters_per_slot + c]).index_count / 3;
    }
    for (const std::uint32_t c : point_plants)
        list.instances_by_representation[std::size_t(representation::points)] += c;
    for (const std::uint32_t c : eco_plants)
        list.instances_by_representation[std::size_t(representation::eco_tile)] += c;
    for (const std::uint32_t c : shell_plants)
        list.instances_by_representation[std::size_t(representation::shell)] += c;
}

}  // namespace sylva
