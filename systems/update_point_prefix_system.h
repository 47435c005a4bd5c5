#pragma once
// Deussen 2002 §5: for every plant drawn with the point/line representation, how much of each
// part to draw this frame: Eq. 1 and the §5.3 blend for point parts, Eq. 2 for line parts,
// each with r the distance from the eye to the part's centre (so the parts of one plant, and
// the octree cells of a big one, §6.1, choose independently). §4.3 importance keeps
// important parts polygonal longer (point_line_lod.h: blend_points, select_lines).
// The device's primitive costs (a resource, primitive_costs: measured where Sylva runs, the
// paper's 1:3 point:triangle otherwise) set where parts turn polygonal. Writes the prefix
// lengths (point_prefix; cell_prefix for the octree cells of big plants, §6.1) that
// build_draw_list draws, in parallel chunks.
#include <optional>

#include "components/camera.h"
#include "components/fade_alpha.h"
#include "components/lod_state.h"
#include "components/octree_cell.h"
#include "components/plant_instance.h"
#include "components/point_prefix.h"
#include "components/transform.h"
#include "ecs/system.h"
#include "resources/lod_policy.h"
#include "resources/scene_assets.h"

namespace sylva {

// Which parts a plant or an octree cell draws: lod_parts[first, first + count).
struct part_range {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
};
part_range parts_of(const species_entry& species);
part_range parts_of(const lod_cell_entry& cell);

// The prefixes of a plant's (or cell's) parts: `sample_distance` is d' in image-plane units.
// Point and splat counts are rounded down after adding sample_dither(dither_seed, part)
// (nullopt: plain rounding down for points, to nearest for splats). With `fade_last` (soft
// splats), a part drawn as points only draws ⌈p⌉ of them instead, the last faded to p − ⌊p⌋
// (point_prefix::last_fade). With `fog_density_per_m`, points and splats are spaced by
// fog_sample_distance at each part's distance (point_line_lod.h); lines keep d'.
point_prefix compute_point_prefix(const species_library& library, part_range parts,
                                  const world_transform& t, const glm::dvec3& eye,
                                  double sample_distance, double splat_factor,
                                  const primitive_costs& costs = {},
                                  std::optional<std::uint32_t> dither_seed = std::nullopt,
                                  bool fade_last = false, double fog_density_per_m = 0.0);

// The prefixes of one plant in a shadow cascade sampled every `texel_world_m` metres: that is
// the sample distance there (the shadow map sees every part at its own size, so Eq. 1 becomes
// p = c_p·½·A/τ² and Eq. 2 q = A/(l·τ), with ε_l >= τ for polygons), with c_p = 1: shadow
// splats τ wide then cover exactly the leaf area (point_line_lod.h k_shadow_sample_texels).
point_prefix compute_shadow_prefix(const species_library& library, part_range parts, float scale,
                                   double texel_world_m, const primitive_costs& costs = {});

// A part's centre in world space (the instance's position, yaw and scale applied).
glm::dvec3 part_world_center(const lod_part_entry& part, const world_transform& t);

struct update_point_prefix_system {
    static constexpr std::string_view k_name = "update_point_prefix";
    static constexpr ecs::phase k_phase = ecs::phase::transition;
    using reads = ecs::reads<camera, world_transform, plant_instance, lod_state, fade_alpha, octree_cell,
                             species_library, lod_policy, primitive_costs>;
    using writes = ecs::writes<point_prefix, cell_prefix>;
    static void run(ecs::system_context<update_point_prefix_system>& ctx);
};

}  // namespace sylva
