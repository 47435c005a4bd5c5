#include "systems/update_point_prefix_system.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "ecs/parallel.h"
#include "lighting/fog.h"

namespace sylva {

static_assert(k_prefix_parts == k_max_cell_parts, "one prefix per part of a cell");

glm::dvec3 part_world_center(const lod_part_entry& part, const world_transform& t) {
    // The same yaw rotation as shaders/surface.vert: x' = c·x + s·z, z' = −s·x + c·z.
    const double c = std::cos(double(t.yaw)), s = std::sin(double(t.yaw));
    const glm::dvec3 m = glm::dvec3(part.center) * double(t.scale);
    return t.position + glm::dvec3(c * m.x + s * m.z, m.y, -s * m.x + c * m.z);
}

part_range parts_of(const species_entry& species) { return {species.first_lod_part, species.lod_part_count}; }
part_range parts_of(const lod_cell_entry& cell) { return {cell.first_lod_part, cell.lod_part_count}; }

point_prefix compute_point_prefix(const species_library& library, part_range parts,
                                  const world_transform& t, const glm::dvec3& eye,
                                  double sample_distance, double splat_factor,
                                  const primitive_costs& costs,
                                  std::optional<std::uint32_t> dither_seed, bool fade_last,
                                  double fog_density_per_m) {
    point_prefix prefix;
    const double scale = double(t.scale);
    for (std::uint32_t i = 0; i < parts.count && i < k_prefix_parts; ++i) {
        const lod_part_entry& part = library.lod_parts[parts.first + i];
        const double r = glm::length(part_world_center(part, t) - eye);
        const double area = double(part.area_m2) * scale * scale;
        const double dither = dither_seed ? sample_dither(*dither_seed, i) : -1.0;
        const double splat_distance = fog_sample_distance(sample_distance, r, fog_density_per_m);
        part_draw d;
        if (part.primitive == lod_primitive::points) {
            const double exact = required_points(area, r, splat_distance, splat_factor);
            const double p = !fade_last && dither >= 0.0 ? std::floor(exact + dither) : exact;
            const auto after =
                std::span(library.points_after).subspan(part.first_after, part.triangle_count + 1);
            d = blend_points(p, part.triangle_count, after, costs, part.importance);
            // Soft splats, points only: the whole splats blend_points drew (⌊p⌋, when n_p did not
            // cap them) and one more, faded to the fraction of p beyond them.
            const double whole = std::floor(exact);
            if (fade_last && d.triangles == 0 && exact > whole && double(d.primitives) == whole &&
                whole + 1.0 <= double(after[0])) {
                d.primitives += 1;
                prefix.last_fade[i] = std::uint8_t(std::lround(255.0 * (whole + 1.0 - exact)));
            }
        } else {
            d = select_lines_fogged(area, double(part.line_length_m) * scale,
                                    double(part.line_error_m) * scale, part.primitive_count,
                                    part.triangle_count, r, sample_distance, splat_distance, costs,
                                    part.importance, splat_factor, dither >= 0.0 ? dither : 0.5);
        }
        prefix.triangles[i] = d.triangles;
        prefix.primitives[i] = d.primitives;
        prefix.splats[i] = d.splats ? 1 : 0;
    }
    return prefix;
}

point_prefix compute_shadow_prefix(const species_library& library, part_range parts, float scale,
                                   double texel_world_m, const primitive_costs& costs) {
    constexpr double splat_factor = 1.0;  // casters cover the leaf area exactly
    point_prefix prefix;
    const double s = double(scale);
    for (std::uint32_t i = 0; i < parts.count && i < k_prefix_parts; ++i) {
        const lod_part_entry& part = library.lod_parts[parts.first + i];
        const double area = double(part.area_m2) * s * s;
        part_draw d;
        // At r = 1 the image plane is the world: the texel is d' in metres.
        if (part.primitive == lod_primitive::points) {
            d = blend_points(required_points(area, 1.0, texel_world_m, splat_factor), part.triangle_count,
                             std::span(library.points_after).subspan(part.first_after, part.triangle_count + 1), costs,
                             part.importance);
        } else {
            d = select_lines(area, double(part.line_length_m) * s, double(part.line_error_m) * s, part.primitive_count,
                             part.triangle_count, 1.0, texel_world_m, costs, part.importance, splat_factor);
        }
        prefix.triangles[i] = d.triangles;
        prefix.primitives[i] = d.primitives;
        prefix.splats[i] = d.splats ? 1 : 0;
    }
    return prefix;
}

void update_point_prefix_system::run(ecs::system_context<update_point_prefix_system>& ctx) {
    const lod_policy& policy = ctx.resource<lod_policy>();
    if (!policy.uses_point_lines()) return;  // nothing to do costs nothing
    const camera& cam = ctx.single<camera>();
    const species_library& library = ctx.resource<species_library>();
    const double d = image_plane_units(policy.points.sample_distance_px, cam.fov_y, cam.viewport_height_px);
    const double c_p = policy.points.splat_factor;
    const bool dither = policy.points.dither;
    const bool fade_last = policy.points.splats == splat_style::soft;
    const double fog = policy.points.fog_weighted ? k_fog_density_per_m : 0.0;
    const primitive_costs& costs = ctx.resource<primitive_costs>();
    // A plant drawn as points, whole or as the faded partner of a ladder's band (DESIGN §1.5;
    // build_draw_list draws the partner's first `fade` of these prefixes).
    const auto drawn_as_points = [](const lod_state& lod, const fade_alpha& fade) {
        return lod.current == representation::points || fade.partner == representation::points;
    };
    auto plants =
        ctx.query<const world_transform, const plant_instance, const lod_state, const fade_alpha, point_prefix>();
    ctx.parallel_for(plants.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        plants.each_chunk(begin, end, [&](ecs::entity, const world_transform& t, const plant_instance& p,
                                          const lod_state& lod, const fade_alpha& fade, point_prefix& prefix) {
            if (!drawn_as_points(lod, fade)) {
                prefix = {};
                return;
            }
            const species_entry& species = library.species[static_cast<std::size_t>(p.species)];
            prefix =
                compute_point_prefix(library, parts_of(species), t, cam.position, d, c_p, costs,
                                     dither ? std::optional(p.seed) : std::nullopt, fade_last, fog);
        });
    });
    // §6.1: each octree cell of a big plant chooses on its own, r measured to its parts.
    const auto transforms = ctx.read<world_transform>().data();
    const auto lods = ctx.read<lod_state>().data();
    const auto fades = ctx.read<fade_alpha>().data();
    const auto instances = ctx.read<plant_instance>().data();
    auto cells = ctx.query<const octree_cell, cell_prefix>();
    ctx.parallel_for(cells.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        cells.each_chunk(begin, end, [&](ecs::entity, const octree_cell& cell, cell_prefix& out) {
            if (!drawn_as_points(lods[cell.plant], fades[cell.plant])) {
                out.prefix = {};
                return;
            }
            out.prefix = compute_point_prefix(
                library, parts_of(library.cells[cell.cell]), transforms[cell.plant], cam.position,
                d, c_p, costs,
                dither ? std::optional(instances[cell.plant].seed ^ cell.cell) : std::nullopt,
                fade_last, fog);
        });
    });
}

}  // namespace sylva
