#pragma once
// Which representation an entity is drawn with this frame. Writers: cull (visible),
// select_representation (current, previous). Read by transitions and build_draw_list.
#include <cstdint>

namespace sylva {

// Every representation Sylva can draw. Later work adds points/lines (Deussen 2002), billboard
// clouds and shells (Behrendt 2005) and LoDF foliage clusters (Rebollo 2006).
enum class representation : std::uint8_t {
    none = 0,      // culled or not yet chosen
    mesh_full,     // every triangle and leaf of the model
    mesh_reduced,  // the model generated at reduced detail (fewer segments, fewer larger leaves)
    mesh_far,      // trunk and a few dozen large leaf cards, for trees far away
    // Two vertical quads crossing at the trunk with baked colour and normal atlases
    // (models/crossed_billboard.h): the usual engine baseline beyond the far mesh. Not a mesh
    // level: build_draw_list's coarser() stops at mesh_far and never yields it.
    crossed_billboard,
    points,
    lines,
    billboard_cloud,
    shell,
    foliage_clusters,
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
