#pragma once
// Which representation an entity is drawn with this frame. Writers: cull (visible),
// select_representation (current, previous). Read by transitions and build_draw_list.
#include <cstdint>

namespace sylva {

// Every representation Sylva can draw, and only those: metrics.json and bench.json report an
// instance count per enumerator, so a representation joins the enum when it can be drawn (shells,
// Behrendt 2005 §3, come with their issue).
enum class representation : std::uint8_t {
    none = 0,      // culled or not yet chosen
    mesh_full,     // every triangle and leaf of the model
    mesh_reduced,  // the model generated at reduced detail (fewer segments, fewer larger leaves)
    mesh_far,      // trunk and a few dozen large leaf cards, for trees far away
    // Two vertical quads crossing at the trunk with baked colour and normal atlases
    // (models/bake/crossed_billboard.h): the usual engine baseline beyond the far mesh. Not a mesh
    // level: build_draw_list's coarser() stops at mesh_far and never yields it.
    crossed_billboard,
    // Deussen 2002: prefixes of the plant's random-order triangles, points and lines (one
    // representation for all three; frame_record counts the points and lines it draws).
    points,
    billboard_cloud,  // Behrendt 2005 §2
    // Deussen 2002 §6.2: drawn by its eco tile's aggregated point and line sets
    // (setup/tile_point_sets.h), not on its own. Chosen by a ladder's last rung; a plant whose
    // tile cannot be drawn as its sets falls back to points (systems/aggregate_eco_tiles_system.h).
    eco_tile,
    // Rebollo 2006: the full mesh's trunk and branches, and its foliage at a continuous leaf count
    // by LoDF's leaf collapses (lod/lodf.h), drawn cluster by cluster (systems/update_lodf_system.h).
    lodf,
    // Behrendt 2005 §3: drawn by the shell textures over its terrain (setup/shell_assets.h), not on
    // its own; only a Wang-tiled plant can be, as its ladder's last rung (the shell shows exactly
    // the tiling's plants).
    shell,
    // The crossed billboard with the plant turned about its vertical axis so that the quad whose
    // baked view is nearer the eye's faces it, the other collapsed (a cylindrical billboard with
    // two images; models/bake/crossed_billboard.h facing_billboard_mesh): the crown's width and
    // one quad's fragments from every side, where the crossed pair seen between its quads
    // foreshortens both to 0.71 of it, overlapping, and shades both. It casts the crossed
    // billboard's shadow (lod/ladder.h caster_of), so its shadow does not turn with the eye.
    // Appended so the values above keep their numbers.
    facing_billboard,
    count
};

struct lod_state {
    representation current = representation::none;
    representation previous = representation::none;
    std::uint8_t visible = 0;       // 1 when inside the view frustum and draw distance
    std::uint8_t in_shadow_range = 0;  // 1 when it may cast into the sun's shadow cascades
};
static_assert(sizeof(lod_state) == 4);

}  // namespace sylva
